// The paper's law (Kammer et al. 2014, eq. 1): a constant coefficient mu with the slip-scale
// regularisation of the normal stress, always (the same physics as "coulomb" with
// regularization "slip_scale", which the reader writes as this law). docs/physics.md.
#include "solver/interface/friction/constant_coefficient.hpp"

namespace slipfront {

namespace {

class PrakashClifton final : public ConstantCoefficient {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "prakash_clifton";
      d.meaning = "constant mu with the slip-scale regularisation of paper eq. 1";
      d.parameters = {mu_parameter()};
      return d;
    }();
    return d;
  }
  const char* fixed_regularization() const override { return "slip_scale"; }
  const char* unregularized_law() const override { return "coulomb"; }
};

} // namespace

const CoefficientLaw& prakash_clifton_law() {
  static const PrakashClifton law;
  return law;
}

} // namespace slipfront
