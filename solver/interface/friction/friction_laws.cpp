// The friction laws a job can name: one line per coefficient law and per regularisation
// (docs/architecture.md "Adding a friction law"). Each law lives in a file of its own here.
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

// Defined in their own files.
const CoefficientLaw& constant_coefficient();
const CoefficientLaw& linear_slip_weakening();
const RegularizationLaw& no_regularization();
const RegularizationLaw& slip_scale_regularization();
const RegularizationLaw& time_scale_regularization();

const CoefficientLaw& coefficient_law(FrictionLaw law) {
  switch (law) {
  case FrictionLaw::prakash_clifton:
  case FrictionLaw::coulomb:
    return constant_coefficient();
  case FrictionLaw::slip_weakening:
    return linear_slip_weakening();
  }
  return constant_coefficient();
}

const RegularizationLaw& regularization_law(Regularization regularization) {
  switch (regularization) {
  case Regularization::none:
    return no_regularization();
  case Regularization::slip_scale:
    return slip_scale_regularization();
  case Regularization::time_scale:
    return time_scale_regularization();
  }
  return no_regularization();
}

const char* to_string(FrictionLaw law) {
  switch (law) {
  case FrictionLaw::prakash_clifton:
    return "prakash_clifton";
  case FrictionLaw::coulomb:
    return "coulomb";
  case FrictionLaw::slip_weakening:
    return "slip_weakening";
  }
  return "unknown";
}

const char* to_string(Regularization regularization) {
  switch (regularization) {
  case Regularization::none:
    return "none";
  case Regularization::slip_scale:
    return "slip_scale";
  case Regularization::time_scale:
    return "time_scale";
  }
  return "unknown";
}

Regularization effective_regularization(const Friction& friction) {
  return friction.law == FrictionLaw::prakash_clifton ? Regularization::slip_scale
                                                      : friction.regularization;
}

} // namespace slipfront
