// Constant friction coefficient mu (static = kinetic): the law of "coulomb" and
// "prakash_clifton" (docs/physics.md "Friction").
#include "solver/interface/friction/coefficient_law.hpp"

namespace slipfront {

namespace {

class ConstantCoefficient final : public CoefficientLaw {
public:
  FrictionParameters parameters() const override { return {&FrictionValues::mu}; }
  double static_coefficient(const FrictionValues& v) const override { return v.mu; }
  double coefficient(const FrictionValues& v, double /*slip_path*/) const override { return v.mu; }
};

} // namespace

const CoefficientLaw& constant_coefficient() {
  static const ConstantCoefficient law;
  return law;
}

} // namespace slipfront
