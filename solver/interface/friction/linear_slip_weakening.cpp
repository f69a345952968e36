// Linear slip weakening (Ida 1972; Andrews 1976; docs/physics.md "Friction"): the
// coefficient falls linearly from mu_s to mu_d over the slip path D_c and stays at mu_d,
//   mu(s) = mu_s - (mu_s - mu_d) min(s / D_c, 1),
// with the regularisation the job chooses.
#include "solver/interface/friction/coefficient_law.hpp"

#include "solver/number_text.hpp"

#include <algorithm>

#include <numbers>

namespace slipfront {

namespace {

class LinearSlipWeakening final : public CoefficientLaw {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "slip_weakening";
      d.meaning = "mu from mu_s to mu_d over D_c of slip path";
      d.label = "slip weakening D_c = {D_c} m";
      d.parameters = {
          {"mu_s", &FrictionValues::mu_s, "", "static coefficient", Bounds::non_negative()},
          {"mu_d", &FrictionValues::mu_d, "", "dynamic coefficient, at most mu_s",
           Bounds::non_negative()},
          {"D_c", &FrictionValues::D_c, "m", "slip-weakening distance", Bounds::positive()}};
      d.check = [](const FrictionValues& v) -> std::optional<ValueProblem> {
        if (v.mu_d <= v.mu_s) return std::nullopt;
        return ValueProblem{{&FrictionValues::mu_s, &FrictionValues::mu_d},
                            "mu_d = " + number_text(v.mu_d, 12) + " exceeds mu_s = " +
                                number_text(v.mu_s, 12) + " (the coefficient weakens)"};
      };
      return d;
    }();
    return d;
  }
  bool well_posed_unregularized(const SimulationParams&, std::string& why) const override {
    why = "not judged for slip-weakening friction (weakening makes Coulomb ill-posed at smaller "
          "friction coefficients too)";
    return false;
  }
  double static_coefficient(const FrictionValues& v) const override { return v.mu_s; }
  double coefficient(const FrictionValues& v, const FrictionState& state,
                     double /*slip_rate*/) const override {
    return v.mu_s - (v.mu_s - v.mu_d) * std::min(state.slip_path / v.D_c, 1.0);
  }
  std::optional<Weakening> weakening(const FrictionValues& v) const override {
    // The static process zone of Palmer & Rice (1973), as Day et al. (2005) write it.
    return Weakening{v.mu_s - v.mu_d, v.D_c, 9.0 * std::numbers::pi / 32.0,
                     "the slip-weakening process zone, (9 pi / 32) mu* D_c / ((mu_s - mu_d) "
                     "|normal_stress|)"};
  }
};

} // namespace

const CoefficientLaw& linear_slip_weakening_law() {
  static const LinearSlipWeakening law;
  return law;
}

} // namespace slipfront
