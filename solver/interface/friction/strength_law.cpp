#include "solver/interface/friction/strength_law.hpp"

#include <algorithm>

namespace slipfront {

StrengthLaw::StrengthLaw(const Friction& friction)
    : job_(friction), coefficient_(&coefficient_law(friction)),
      regularization_(&effective_regularization(friction)) {}

FrictionState StrengthLaw::resting_state(const FrictionValues& values, double pressure,
                                         double shear_stress) const {
  return coefficient_->initial_state(job_, values, pressure, shear_stress);
}

double StrengthLaw::normal_stress_seen(const FrictionValues& values,
                                       const FrictionState& state) const {
  const double mu_0 = coefficient_->static_coefficient(values);
  return mu_0 > 0.0 ? state.filtered / mu_0 : 0.0;
}

namespace {

// (mu / mu_0) c*: exactly c* for a constant mu (x / x = 1); mu_0 = 0 holds nothing.
double scaled_strength(const CoefficientLaw& law, const FrictionValues& values,
                       const FrictionState& state, double slip_rate) {
  const double mu_0 = law.static_coefficient(values);
  if (!(mu_0 > 0.0)) return 0.0;
  return law.coefficient(values, state, slip_rate) / mu_0 * state.filtered;
}

} // namespace

double StrengthLaw::strength(const FrictionValues& values, const FrictionState& state,
                             double slip_rate) const {
  return scaled_strength(*coefficient_, values, state, slip_rate);
}

FrictionState StrengthLaw::advance_state(const FrictionValues& values, const FrictionState& state,
                                         double pressure_start, double pressure_end,
                                         double slip_speed, double dt) const {
  const double mu_0 = coefficient_->static_coefficient(values);
  const double c_start = mu_0 * std::max(0.0, pressure_start);
  const double c_end = mu_0 * std::max(0.0, pressure_end);
  FrictionState out = state;
  out.filtered =
      regularization_->advance(values, job_.update, state.filtered, c_start, c_end, slip_speed, dt);
  coefficient_->advance_state(job_, values, out, slip_speed, dt);
  return out;
}

FrictionStep StrengthLaw::advance(const FrictionValues& values, const FrictionState& state,
                                  double pressure_start, double pressure_end, double slip_speed,
                                  double dt) const {
  FrictionStep out;
  out.state = advance_state(values, state, pressure_start, pressure_end, slip_speed, dt);
  out.strength = scaled_strength(*coefficient_, values, out.state, slip_speed);
  return out;
}

bool StrengthLaw::uses(double FrictionValues::*parameter) const {
  return coefficient_->description().uses(parameter) ||
         regularization_->description().uses(parameter);
}

} // namespace slipfront
