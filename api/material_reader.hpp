// Reading a material object of the job JSON (`material`, and any other solid's): either
// {density, young_modulus, poisson_ratio} or {density, p_wave_speed, s_wave_speed}
// (docs/api-job-spec.md "material"; the presets state wave speeds).
#pragma once

#include "api/json_fields.hpp"
#include "solver/params.hpp"

namespace slipfront::api {

// Reads `in` (one material object) into `material`. The wave-speed form is converted with
//   mu = rho c_s^2,  nu = (c_p^2 - 2 c_s^2) / (2 (c_p^2 - c_s^2)),  E = 2 mu (1 + nu)
// and kept as given in the canonical form. Mixing the forms, half a form, and
// c_p <= sqrt(2) c_s (nu <= 0) are errors naming the field.
void read_material(ObjectReader& in, Material& material);

// Whether a material's canonical form is the wave-speed one (the run bounds then name
// p_wave_speed and s_wave_speed instead of poisson_ratio and young_modulus).
bool given_in_wave_speeds(const nlohmann::json& canonical_material);

} // namespace slipfront::api
