// Coulomb friction: the constant coefficient mu, with the regularisation the job chooses
// ("none", the default, is plain Coulomb friction: the strength follows the contact pressure
// at every instant). docs/physics.md "Friction".
#include "solver/interface/friction/constant_coefficient.hpp"

#include "solver/interface/ill_posedness.hpp"

#include <sstream>

namespace slipfront {

LawParameter ConstantCoefficient::mu_parameter() {
  return {"mu", &FrictionValues::mu, "", "friction coefficient, static = kinetic",
          Bounds::non_negative()};
}

bool ConstantCoefficient::well_posed_unregularized(const SimulationParams& params,
                                                   std::string& why) const {
  const double mu = params.friction.mu;
  if (!params.lower.elastic()) {
    const bool small = mu < 1.0;
    std::ostringstream text;
    text << mu; // six significant digits
    why = "an elastic solid on the rigid plane with mu = " + text.str() +
          (small ? " < 1: well-posed (Renardy 1992)"
                 : " >= 1: ill-posed for equal static and kinetic coefficients (Martins et al. "
                   "1995)");
    return small;
  }
  return two_solids_well_posed(params, why);
}

namespace {

class Coulomb final : public ConstantCoefficient {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "coulomb";
      d.meaning = "constant mu, regularisation as chosen";
      d.label_alone = "Coulomb";
      d.parameters = {mu_parameter()};
      // Plain coulomb took L, v_star and strength_update before the regularisation was a
      // choice of its own (they did nothing), and its canonical form has no regularization.
      d.legacy_fields = {"L", "v_star", "strength_update"};
      d.omits_no_regularization = true;
      return d;
    }();
    return d;
  }
};

} // namespace

const CoefficientLaw& coulomb_law() {
  static const Coulomb law;
  return law;
}

} // namespace slipfront
