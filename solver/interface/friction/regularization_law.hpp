// The regularisation of the normal stress that enters the strength (docs/physics.md
// "Regularisation"): the node keeps c* = mu_0 sigma* (mu_0 its static coefficient), which
// follows c = mu_0 max(0, p) by
//   dc*/dt = -k (c* - c),
// with k = (|V| + V*)/L (slip scale, paper eq. 1) or k = 1/t* (time scale); without
// regularisation c* = c at every instant. One file per regularisation beside this one; the
// job's is picked in friction_laws.cpp.
#pragma once

#include "solver/interface/friction/coefficient_law.hpp"

namespace slipfront {

class RegularizationLaw {
public:
  virtual ~RegularizationLaw() = default;
  virtual FrictionParameters parameters() const = 0;
  // c* after one step dt from `filtered` before it, the target going from c_start to c_end
  // over the step, the slip speed |V| over it (strength_update.hpp: the updates).
  virtual double advance(const FrictionValues& values, StrengthUpdate update, double filtered,
                         double c_start, double c_end, double slip_speed, double dt) const = 0;
};

// The regularisation a law runs with: prakash_clifton's is always the slip scale.
Regularization effective_regularization(const Friction& friction);

// Every regularisation (friction.regularization), in the job schema's order
// (friction_laws.cpp).
const std::vector<NamedLaw<Regularization, RegularizationLaw>>& regularization_laws();

// The regularisation law of `regularization`, and its job JSON spelling.
const RegularizationLaw& regularization_law(Regularization regularization);
const char* to_string(Regularization regularization);

} // namespace slipfront
