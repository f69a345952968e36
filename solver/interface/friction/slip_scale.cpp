// The slip-scale regularisation of the simplified Prakash-Clifton law (paper eq. 1):
//   dc*/dt = -(|V| + V*)/L (c* - c),
// a lag over a slip distance L (or a time L/V* without slip).
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/friction/strength_update.hpp"

namespace slipfront {

namespace {

class SlipScale final : public RegularizationLaw {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "slip_scale";
      d.meaning = "paper eq. 1, L and v_star";
      d.label = "L = {L} m";
      d.parameters = {
          {"L", &FrictionValues::L, "m", "characteristic length of the slip-scale regularisation",
           Bounds::positive()},
          {"v_star", &FrictionValues::v_star, "m/s",
           "reference velocity V* of the slip-scale regularisation", Bounds::positive()}};
      d.choices = {strength_update_choice()};
      return d;
    }();
    return d;
  }
  bool slip_filter() const override { return true; }
  double advance(const FrictionValues& v, StrengthUpdate update, double filtered, double c_start,
                 double c_end, double slip_speed, double dt) const override {
    const double x = dt * (slip_speed + v.v_star) / v.L; // k dt
    return filtered_strength(update, filtered, c_start, c_end, x);
  }
};

} // namespace

const RegularizationLaw& slip_scale_regularization() {
  static const SlipScale law;
  return law;
}

} // namespace slipfront
