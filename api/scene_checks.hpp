// The warnings of a valid job (docs/api-job-spec.md "Warnings"): a scene the run can carry out
// but that is likely not the one meant. Each names a field by its JSON pointer and says what
// the run would do and what to change:
//   - a default of the paper's scaled units kept for another material (api/scene_defaults.hpp);
//   - a stress out of scale with the shear modulus;
//   - a slip-weakening process zone that few elements resolve (Day et al. 2005);
//   - an arrest window the run leaves no room for;
//   - a probe inside the nucleation patch, or every station;
//   - a duration too short for a wave to cross the nucleation patch, or for the ellipse to end.
// A scene the physics cannot run is an error of the validation instead (api/job_checks.hpp).
#pragma once

#include "api/job_spec.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace slipfront::api {

// The smallest number of elements across the static process zone that gives no warning.
inline constexpr double min_process_zone_elements = 3.0;

// Call it for a job without errors, after api/scene_defaults.hpp filled its provenance.
std::vector<FieldWarning> scene_warnings(const JobSpec& job);

// The static process zone of the law (its Weakening): linear slip weakening (Day et al. 2005)
//   Lambda_0 = (9 pi / 32) mu* D_c / ((mu_s - mu_d) |normal_stress|),
// rate-and-state (Ampuero & Rubin 2008) Lambda_0 = mu* D_c / (b |normal_stress|), with
// mu* = 2 / ((1 - nu+)/mu+ + (1 - nu-)/mu-) (mu / (1 - nu) for two identical solids, 2 mu
// / (1 - nu) on the rigid plane, where only one side deforms) [m]; NaN for a law that does not
// weaken.
double static_process_zone(const SimulationParams& params);

// The record's resolution (docs/api-job-spec.md "Warnings"): {process_zone [m], elements (its
// length over dx), formula}, null for a law that does not weaken.
nlohmann::json resolution_json(const SimulationParams& params);

} // namespace slipfront::api
