// The frictional strength of the law a job chose, node by node and step by step
// (docs/physics.md "Friction", "Regularisation"):
//   strength = mu(s) sigma*,
// with mu(s) the coefficient law (coefficient_law.hpp) of the slip path s and sigma* the
// normal stress seen by friction (regularization_law.hpp). The state a node keeps is
// c* = mu_0 sigma*, mu_0 = mu(0) its static coefficient, so that the strength is
//   strength = (mu(s) / mu_0) c*:
// the regularisation filters mu_0 max(0, p), and for a constant mu the ratio is exactly 1,
// so the constant-mu laws are bit for bit those of the paper's code.
#pragma once

#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

// What a node keeps of its friction from step to step.
struct FrictionState {
  double filtered = 0;  // c* = mu_0 sigma* [Pa]
  double slip_path = 0; // s = integral of |V| dt [m]
};

struct FrictionStep {
  FrictionState state;
  double strength = 0; // [Pa]
};

class StrengthLaw {
public:
  explicit StrengthLaw(const Friction& friction = {});

  // At rest under the contact pressure p: c* = mu_0 max(0, p), no slip.
  FrictionState resting_state(const FrictionValues& values, double pressure) const;
  double strength(const FrictionValues& values, const FrictionState& state) const;
  // One step dt from `state`: the pressure goes from pressure_start to pressure_end over
  // it, slip_speed is |V| over it (it also advances the slip path).
  FrictionStep advance(const FrictionValues& values, const FrictionState& state,
                       double pressure_start, double pressure_end, double slip_speed,
                       double dt) const;

  // Whether the law reads this value (a profile may set only these).
  bool uses(double FrictionValues::*parameter) const;
  const CoefficientLaw& coefficient() const { return *coefficient_; }

private:
  const CoefficientLaw* coefficient_;
  const RegularizationLaw* regularization_;
  StrengthUpdate update_;
};

} // namespace slipfront
