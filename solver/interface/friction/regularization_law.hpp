// The regularisation of the normal stress that enters the strength (docs/physics.md
// "Regularisation"): the node keeps c* = mu_0 sigma* (mu_0 its static coefficient), which
// follows c = mu_0 max(0, p) by
//   dc*/dt = -k (c* - c),
// with k = (|V| + V*)/L (slip scale, paper eq. 1) or k = 1/t* (time scale); without
// regularisation c* = c at every instant. Any coefficient law runs with any regularisation.
// One file per regularisation beside this one, registered in friction_laws.cpp.
#pragma once

#include "solver/interface/friction/coefficient_law.hpp"

namespace slipfront {

class RegularizationLaw {
public:
  virtual ~RegularizationLaw() = default;
  virtual const LawDescription& description() const = 0;
  // Whether c* lags c: false only for "none" (the strength follows the pressure at once).
  virtual bool filters() const { return true; }
  // Whether the filter is the slip scale's, A/A0 = 1/sqrt(1 + (2 pi f L/(V* + |V|))^2) (paper
  // eq. 1 at a frozen |V|): the spectral L_c estimate of docs/metrics.md rests on it.
  virtual bool slip_filter() const { return false; }
  // c* after one step dt from `filtered` before it, the target going from c_start to c_end
  // over the step, the slip speed |V| over it (strength_update.hpp: the updates).
  virtual double advance(const FrictionValues& values, StrengthUpdate update, double filtered,
                         double c_start, double c_end, double slip_speed, double dt) const = 0;
};

// The regularisation a job's friction runs with: the law's fixed one, else the job's choice.
const RegularizationLaw& effective_regularization(const Friction& friction);

// Every regularisation (friction.regularization), in the job schema's order, with those a
// test registered after them; the one of that name, or null; adding one (tests).
const std::vector<const RegularizationLaw*>& regularization_laws();
const RegularizationLaw* find_regularization_law(std::string_view name);
void register_regularization_law(const RegularizationLaw& law);

} // namespace slipfront
