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
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "time_scale";
      d.meaning = "t_star";
      d.label = "t* = {t_star} s";
      d.parameters = {{"t_star", &FrictionValues::t_star, "s",
                       "time of the time-scale regularisation", Bounds::positive()}};
      d.choices = {strength_update_choice()};
      return d;
    }();
    return d;
  }
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
