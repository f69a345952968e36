// A toy friction law that only the tests know: exponential weakening,
//   mu(s) = mu_d + (mu_s - mu_d) exp(-s / D_c),
// written as docs/architecture.md "Adding a friction law" says, in this one file and
// registered from it. The tests linked with it check that the job schema, the reader's
// validation, the web form and the labels all know it with no other edit
// (toy_law_test.cpp, tests/web/test_toy_law_form.py).
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/number_text.hpp"

#include <cmath>

namespace slipfront {

namespace {

class ExponentialWeakening final : public CoefficientLaw {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "exponential_weakening";
      d.meaning = "mu from mu_s towards mu_d, exp(-s/D_c) of the slip path s";
      d.label = "exponential weakening D_c = {D_c} m";
      d.parameters = {
          {"mu_s", &FrictionValues::mu_s, "", "static coefficient", Bounds::non_negative()},
          {"mu_d", &FrictionValues::mu_d, "", "dynamic coefficient, at most mu_s",
           Bounds::non_negative()},
          {"D_c", &FrictionValues::D_c, "m", "weakening distance", Bounds::positive()}};
      d.check = [](const FrictionValues& v) -> std::optional<ValueProblem> {
        if (v.mu_d <= v.mu_s) return std::nullopt;
        return ValueProblem{{&FrictionValues::mu_s, &FrictionValues::mu_d},
                            "mu_d = " + number_text(v.mu_d, 12) +
                                " exceeds mu_s = " + number_text(v.mu_s, 12) + " (it weakens)"};
      };
      return d;
    }();
    return d;
  }
  bool well_posed_unregularized(const SimulationParams&, std::string& why) const override {
    why = "not judged for weakening friction";
    return false;
  }
  double static_coefficient(const FrictionValues& v) const override { return v.mu_s; }
  double coefficient(const FrictionValues& v, const FrictionState& state,
                     double /*slip_rate*/) const override {
    return v.mu_d + (v.mu_s - v.mu_d) * std::exp(-state.slip_path / v.D_c);
  }
};

// Registered when the test executable starts.
const bool registered = [] {
  static const ExponentialWeakening law;
  register_coefficient_law(law);
  return true;
}();

} // namespace

} // namespace slipfront
