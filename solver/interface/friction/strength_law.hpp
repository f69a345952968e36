// The frictional strength of the law a job chose, node by node and step by step
// (docs/physics.md "Friction", "Regularisation"):
//   strength = mu sigma*,
// with mu the coefficient law (coefficient_law.hpp) and sigma* the normal stress seen by
// friction (regularization_law.hpp). The state a node keeps is c* = mu_0 sigma*, mu_0 the
// law's static coefficient, so that the strength is
//   strength = (mu / mu_0) c*:
// the regularisation filters mu_0 max(0, p), and for a constant mu the ratio is exactly 1,
// so the constant-mu laws are bit for bit those of the paper's code.
#pragma once

#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

struct FrictionStep {
  FrictionState state;
  double strength = 0; // [Pa]
};

class StrengthLaw {
public:
  explicit StrengthLaw(const Friction& friction = {});

  // At rest under the contact pressure p and the shear stress tau: c* = mu_0 max(0, p), no
  // slip, and the state of a law of the slip rate (coefficient_law.hpp).
  FrictionState resting_state(const FrictionValues& values, double pressure,
                              double shear_stress = 0.0) const;
  // mu sigma* in `state` at the slip rate |V| (laws of the slip path ignore it).
  double strength(const FrictionValues& values, const FrictionState& state,
                  double slip_rate = 0.0) const;
  // One step dt from `state`: the pressure goes from pressure_start to pressure_end over
  // it, slip_speed is |V| over it (it also advances the slip path and the law's state).
  FrictionStep advance(const FrictionValues& values, const FrictionState& state,
                       double pressure_start, double pressure_end, double slip_speed,
                       double dt) const;
  // The state of advance() without its strength (a law of the slip rate finds its strength
  // in the solve of the slip rate instead).
  FrictionState advance_state(const FrictionValues& values, const FrictionState& state,
                              double pressure_start, double pressure_end, double slip_speed,
                              double dt) const;
  // sigma* of a state: c* / mu_0 (0 when mu_0 is 0).
  double normal_stress_seen(const FrictionValues& values, const FrictionState& state) const;

  // Whether the law reads this value (a profile may set only these).
  bool uses(double FrictionValues::*parameter) const;
  const CoefficientLaw& coefficient() const { return *coefficient_; }
  const RegularizationLaw& regularization() const { return *regularization_; }

private:
  Friction job_; // the law's choices
  const CoefficientLaw* coefficient_;
  const RegularizationLaw* regularization_;
};

} // namespace slipfront
