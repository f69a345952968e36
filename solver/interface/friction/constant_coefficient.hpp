// A constant friction coefficient mu (static = kinetic), the coefficient of "coulomb"
// (coulomb.cpp) and of "prakash_clifton" (prakash_clifton.cpp): docs/physics.md "Friction".
#pragma once

#include "solver/interface/friction/coefficient_law.hpp"

namespace slipfront {

class ConstantCoefficient : public CoefficientLaw {
public:
  bool constant() const override { return true; }
  // On the rigid plane well-posed when mu < 1 (Renardy 1992; Martins et al. 1995: ill-posed
  // only when the static and kinetic coefficients are equal and at least one); between two
  // identical solids well-posed (slip does not change the normal traction); between two
  // different solids ill-posed (Adams 1995; Ranjith & Rice 2001).
  bool well_posed_unregularized(const SimulationParams& params, std::string& why) const override;
  double static_coefficient(const FrictionValues& v) const override { return v.mu; }
  double coefficient(const FrictionValues& v, const FrictionState&, double) const override {
    return v.mu;
  }

protected:
  // mu, as both laws describe it.
  static LawParameter mu_parameter();
};

} // namespace slipfront
