// The slip-scale regularisation of the simplified Prakash-Clifton law (paper eq. 1):
//   dc*/dt = -(|V| + V*)/L (c* - c),
// a lag over a slip distance L (or a time L/V* without slip).
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/friction/strength_update.hpp"

namespace slipfront {

namespace {

class SlipScale final : public RegularizationLaw {
public:
  FrictionParameters parameters() const override {
    return {&FrictionValues::L, &FrictionValues::v_star};
  }
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
