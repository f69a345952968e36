#include "solver/interface/prakash_clifton.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront {

const char* to_string(StrengthUpdate update) {
  switch (update) {
  case StrengthUpdate::exponential_ramp:
    return "exponential_ramp";
  case StrengthUpdate::exponential:
    return "exponential";
  case StrengthUpdate::explicit_euler:
    return "explicit_euler";
  }
  return "unknown";
}

double prakash_clifton_strength(const Friction& friction, double strength, double pressure_start,
                                double pressure_end, double slip_speed, double dt) {
  const double c_end = friction.mu * std::max(0.0, pressure_end);
  const double x = dt * (slip_speed + friction.v_star) / friction.L;
  switch (friction.update) {
  case StrengthUpdate::explicit_euler:
    return strength - x * (strength - c_end);
  case StrengthUpdate::exponential:
    return c_end + (strength - c_end) * std::exp(-x);
  case StrengthUpdate::exponential_ramp:
    break;
  }
  // e = tau - c obeys e' = -k e - s with s = (c_end - c_start)/dt constant over the step:
  // e(dt) = e(0) exp(-x) - (s/k)(1 - exp(-x)), and s/k = (c_end - c_start)/x.
  const double c_start = friction.mu * std::max(0.0, pressure_start);
  const double one_minus_decay = -std::expm1(-x);                 // accurate for small x
  const double ramp_weight = x > 0.0 ? one_minus_decay / x : 1.0; // limit x -> 0
  return c_end + (strength - c_start) * (1.0 - one_minus_decay) - (c_end - c_start) * ramp_weight;
}

} // namespace slipfront
