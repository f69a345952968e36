// The friction laws a job can name: one line per coefficient law and per regularisation in
// the tables below, which give each its job JSON spelling (the reader's choices come from
// here) and its implementation (docs/architecture.md "Adding a friction law"). Each law
// lives in a file of its own beside this one.
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

// Defined in their own files.
const CoefficientLaw& constant_coefficient();
const CoefficientLaw& linear_slip_weakening();
const RegularizationLaw& no_regularization();
const RegularizationLaw& slip_scale_regularization();
const RegularizationLaw& time_scale_regularization();

const std::vector<NamedLaw<FrictionLaw, CoefficientLaw>>& coefficient_laws() {
  static const std::vector<NamedLaw<FrictionLaw, CoefficientLaw>> laws = {
      {FrictionLaw::prakash_clifton, "prakash_clifton", &constant_coefficient()},
      {FrictionLaw::coulomb, "coulomb", &constant_coefficient()},
      {FrictionLaw::slip_weakening, "slip_weakening", &linear_slip_weakening()},
  };
  return laws;
}

const std::vector<NamedLaw<Regularization, RegularizationLaw>>& regularization_laws() {
  static const std::vector<NamedLaw<Regularization, RegularizationLaw>> laws = {
      {Regularization::none, "none", &no_regularization()},
      {Regularization::slip_scale, "slip_scale", &slip_scale_regularization()},
      {Regularization::time_scale, "time_scale", &time_scale_regularization()},
  };
  return laws;
}

namespace {

template <class Kind, class Law>
const NamedLaw<Kind, Law>& entry(const std::vector<NamedLaw<Kind, Law>>& table, Kind kind) {
  for (const auto& named : table)
    if (named.kind == kind) return named;
  return table.front(); // unreachable: every value of the enum has its line
}

} // namespace

const CoefficientLaw& coefficient_law(FrictionLaw law) {
  return *entry(coefficient_laws(), law).law;
}

const RegularizationLaw& regularization_law(Regularization regularization) {
  return *entry(regularization_laws(), regularization).law;
}

const char* to_string(FrictionLaw law) {
  return entry(coefficient_laws(), law).name;
}

const char* to_string(Regularization regularization) {
  return entry(regularization_laws(), regularization).name;
}

Regularization effective_regularization(const Friction& friction) {
  return friction.law == FrictionLaw::prakash_clifton ? Regularization::slip_scale
                                                      : friction.regularization;
}

} // namespace slipfront
