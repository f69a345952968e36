// The time-scale regularisation (as in SEM2DPACK, SeisSol, Akantu; docs/physics.md
// "Regularisation"):
//   dc*/dt = -(c* - c) / t*,
// a lag of the time t* whatever the slip speed.
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/friction/strength_update.hpp"

namespace slipfront {

namespace {

class TimeScale final : public RegularizationLaw {
public:
  FrictionParameters parameters() const override { return {&FrictionValues::t_star}; }
  double advance(const FrictionValues& v, StrengthUpdate update, double filtered, double c_start,
                 double c_end, double /*slip_speed*/, double dt) const override {
    return filtered_strength(update, filtered, c_start, c_end, dt / v.t_star);
  }
};

} // namespace

const RegularizationLaw& time_scale_regularization() {
  static const TimeScale law;
  return law;
}

} // namespace slipfront
