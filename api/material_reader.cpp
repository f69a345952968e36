#include "api/material_reader.hpp"

#include "api/number_text.hpp"

#include <cmath>

namespace slipfront::api {

namespace {

const Interval poisson_range = open_interval(0.0, 0.5);

std::string text(double value) {
  return number_text(value, 12);
}

// The wave speeds of the form {density, p_wave_speed, s_wave_speed} into E and nu.
void read_wave_speeds(ObjectReader& in, Material& material) {
  double c_p = material.p_wave_speed(), c_s = material.s_wave_speed();
  const bool has_p = in.raw("p_wave_speed") != nullptr, has_s = in.raw("s_wave_speed") != nullptr;
  if (!has_p) in.error("p_wave_speed", "is required with s_wave_speed (give both wave speeds)");
  if (!has_s) in.error("s_wave_speed", "is required with p_wave_speed (give both wave speeds)");
  const std::size_t errors_before = in.error_count();
  in.number("p_wave_speed", c_p, positive());
  in.number("s_wave_speed", c_s, positive());
  if (!has_p || !has_s || in.error_count() != errors_before) return;
  // nu = (1 - 2 r) / (2 (1 - r)) with r = (c_s / c_p)^2: no overflow for any finite speeds.
  const double r = (c_s / c_p) * (c_s / c_p);
  const double nu = (1.0 - 2.0 * r) / (2.0 * (1.0 - r));
  if (!(r < 0.5)) {
    in.error("p_wave_speed",
             "must be more than sqrt(2) * s_wave_speed = " + text(std::sqrt(2.0) * c_s) +
                 " m/s, got " + text(c_p) +
                 ": the Poisson ratio (c_p^2 - 2 c_s^2) / (2 (c_p^2 - c_s^2)) would be " +
                 text(nu) +
                 ", and the solver takes poisson_ratio in (0, 0.5) only (its "
                 "kernels and tests cover that range)");
    return;
  }
  if (!poisson_range.contains(nu)) { // c_p / c_s so large that nu rounds to 0.5
    in.error("p_wave_speed", "makes c_p / c_s = " + text(c_p / c_s) +
                                 " so large that the Poisson ratio rounds to " + text(nu) +
                                 " (incompressible), outside (0, 0.5)");
    return;
  }
  const double young = 2.0 * material.density * c_s * c_s * (1.0 + nu);
  if (!(std::isfinite(young) && young > 0.0)) {
    in.error("s_wave_speed", "gives young_modulus = 2 density s_wave_speed^2 (1 + nu) = " +
                                 text(young) + " Pa, not a finite number > 0 for a double");
    return;
  }
  material.young_modulus = young;
  material.poisson_ratio = nu;
}

} // namespace

void read_material(ObjectReader& in, Material& material) {
  in.number("density", material.density, positive());
  const bool speeds = in.raw("p_wave_speed") != nullptr || in.raw("s_wave_speed") != nullptr;
  const std::string mixed =
      "cannot be mixed with p_wave_speed and s_wave_speed: give {density, young_modulus, "
      "poisson_ratio} or {density, p_wave_speed, s_wave_speed}";
  if (speeds) {
    in.reject("young_modulus", mixed, number_schema(positive()));
    in.reject("poisson_ratio", mixed, number_schema(poisson_range));
    read_wave_speeds(in, material);
    return;
  }
  in.number("young_modulus", material.young_modulus, positive());
  in.number("poisson_ratio", material.poisson_ratio, poisson_range);
  // The other form: no default (the moduli above are the default material).
  in.describe("p_wave_speed", number_schema(positive()));
  in.describe("s_wave_speed", number_schema(positive()));
}

bool given_in_wave_speeds(const nlohmann::json& canonical_material) {
  return canonical_material.is_object() && canonical_material.contains("s_wave_speed");
}

} // namespace slipfront::api
