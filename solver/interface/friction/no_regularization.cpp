// No regularisation: the strength follows the contact pressure at every instant,
// c* = mu_0 max(0, p) (plain Coulomb friction for a constant mu).
#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

namespace {

class NoRegularization final : public RegularizationLaw {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "none";
      d.meaning = "the contact pressure";
      return d;
    }();
    return d;
  }
  bool filters() const override { return false; }
  double advance(const FrictionValues& /*values*/, StrengthUpdate /*update*/, double /*filtered*/,
                 double /*c_start*/, double c_end, double /*slip_speed*/,
                 double /*dt*/) const override {
    return c_end;
  }
};

} // namespace

const RegularizationLaw& no_regularization() {
  static const NoRegularization law;
  return law;
}

} // namespace slipfront
