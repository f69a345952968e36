#include "solver/interface/friction/strength_update.hpp"

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

LawChoice strength_update_choice() {
  return {"strength_update",
          "how the strength ODE is advanced in a step (docs/physics.md): exact for \\|V\\| "
          "frozen and p linear over the step (second order); exact for \\|V\\| and p frozen at "
          "the step's end (the reference scheme of docs/physics.md, first order); or forward "
          "Euler (unstable once dt k > 2, k = (\\|V\\|+V*)/L or 1/t*; for failure studies)",
          {"exponential_ramp", "exponential", "explicit_euler"},
          [](const Friction& f) { return int(f.update); },
          [](Friction& f, int i) { f.update = StrengthUpdate(i); }};
}

double filtered_strength(StrengthUpdate update, double filtered, double c_start, double c_end,
                         double x) {
  switch (update) {
  case StrengthUpdate::explicit_euler:
    return filtered - x * (filtered - c_end);
  case StrengthUpdate::exponential:
    return c_end + (filtered - c_end) * std::exp(-x);
  case StrengthUpdate::exponential_ramp:
    break;
  }
  // e = c* - c obeys e' = -k e - s with s = (c_end - c_start)/dt constant over the step:
  // e(dt) = e(0) exp(-x) - (s/k)(1 - exp(-x)), and s/k = (c_end - c_start)/x.
  const double one_minus_decay = -std::expm1(-x);                 // accurate for small x
  const double ramp_weight = x > 0.0 ? one_minus_decay / x : 1.0; // limit x -> 0
  return c_end + (filtered - c_start) * (1.0 - one_minus_decay) - (c_end - c_start) * ramp_weight;
}

} // namespace slipfront
