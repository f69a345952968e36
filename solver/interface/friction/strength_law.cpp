#include "solver/interface/friction/strength_law.hpp"

#include <algorithm>

namespace slipfront {

StrengthLaw::StrengthLaw(const Friction& friction)
    : coefficient_(&coefficient_law(friction.law)),
      regularization_(&regularization_law(effective_regularization(friction))),
      update_(friction.update) {}

FrictionState StrengthLaw::resting_state(const FrictionValues& values, double pressure) const {
  return {coefficient_->static_coefficient(values) * std::max(0.0, pressure), 0.0};
}

namespace {

// (mu(s) / mu_0) c*: exactly c* for a constant mu (x / x = 1); mu_0 = 0 holds nothing.
double scaled_strength(const CoefficientLaw& law, const FrictionValues& values, double mu_0,
                       const FrictionState& state) {
  if (!(mu_0 > 0.0)) return 0.0;
  return law.coefficient(values, state.slip_path) / mu_0 * state.filtered;
}

} // namespace

double StrengthLaw::strength(const FrictionValues& values, const FrictionState& state) const {
  return scaled_strength(*coefficient_, values, coefficient_->static_coefficient(values), state);
}

FrictionStep StrengthLaw::advance(const FrictionValues& values, const FrictionState& state,
                                  double pressure_start, double pressure_end, double slip_speed,
                                  double dt) const {
  const double mu_0 = coefficient_->static_coefficient(values);
  const double c_start = mu_0 * std::max(0.0, pressure_start);
  const double c_end = mu_0 * std::max(0.0, pressure_end);
  FrictionStep out;
  out.state.filtered =
      regularization_->advance(values, update_, state.filtered, c_start, c_end, slip_speed, dt);
  out.state.slip_path = state.slip_path + dt * slip_speed;
  out.strength = scaled_strength(*coefficient_, values, mu_0, out.state);
  return out;
}

bool StrengthLaw::uses(double FrictionValues::*parameter) const {
  const FrictionParameters a = coefficient_->parameters(), b = regularization_->parameters();
  return std::find(a.begin(), a.end(), parameter) != a.end() ||
         std::find(b.begin(), b.end(), parameter) != b.end();
}

} // namespace slipfront
