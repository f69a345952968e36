// The friction laws (solver/interface/friction/): linear slip weakening against its
// closed form, the state c* = mu_0 sigma* that keeps the constant-mu laws bit for bit those
// of the paper's code, the slip path, and the laws' parameters (docs/physics.md "Friction").
#include "solver/interface/friction/strength_law.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

Friction slip_weakening(const std::string& regularization = "none") {
  Friction f;
  f.law = "slip_weakening";
  f.mu_s = 0.677;
  f.mu_d = 0.525;
  f.D_c = 0.4;
  f.regularization = regularization;
  return f;
}

TEST(FrictionLaws, LinearSlipWeakeningCoefficient) {
  const Friction f = slip_weakening();
  const CoefficientLaw& law = coefficient_law(f);
  EXPECT_EQ(law.static_coefficient(f), 0.677);
  EXPECT_EQ(law.coefficient(f, {0.0, 0.0, 0.0}, 0.0), 0.677);
  EXPECT_DOUBLE_EQ(law.coefficient(f, {0.0, 0.2, 0.0}, 0.0), 0.5 * (0.677 + 0.525)); // D_c / 2
  EXPECT_DOUBLE_EQ(law.coefficient(f, {0.0, 0.4, 0.0}, 0.0), 0.525);                 // D_c
  EXPECT_EQ(law.coefficient(f, {0.0, 0.8, 0.0}, 0.0), 0.525); // 2 D_c: stays at mu_d
  EXPECT_EQ(law.coefficient(f, {0.0, 1e9, 0.0}, 0.0), 0.525);
}

TEST(FrictionLaws, SlipWeakeningStrengthFollowsTheSlipPath) {
  // Without regularisation: strength = mu(s) max(0, p), s = sum of dt |V| over the steps.
  const Friction f = slip_weakening();
  const StrengthLaw law(f);
  const double p = 120e6, dt = 1e-3;
  FrictionState state = law.resting_state(f, p);
  EXPECT_EQ(state.filtered, 0.677 * p);
  EXPECT_EQ(law.strength(f, state), 0.677 * p);
  for (int n = 1; n <= 1000; ++n) {
    const double speed = n % 2 ? 1.0 : 0.6; // |V| alternating, mean 0.8 m/s
    const FrictionStep step = law.advance(f, state, p, p, speed, dt);
    state = step.state;
    const double s = state.slip_path;
    const double mu = 0.677 - (0.677 - 0.525) * std::min(s / 0.4, 1.0);
    ASSERT_NEAR(step.strength, mu * p, 1e-9 * p) << "step " << n;
  }
  EXPECT_NEAR(state.slip_path, 0.8, 1e-12); // 1000 steps of 1 ms at 0.8 m/s on average
  EXPECT_NEAR(law.strength(f, state), 0.525 * p, 1e-9 * p);
  // An open node (p < 0) holds nothing, whatever its slip.
  EXPECT_EQ(law.advance(f, state, p, -1.0, 1.0, dt).strength, 0.0);
}

TEST(FrictionLaws, RegularisationFiltersMuZeroTimesThePressure) {
  // Slip weakening with the time scale: c* follows mu_s max(0, p) with the time t*, and the
  // strength is (mu(s) / mu_s) c* (strength_law.hpp).
  Friction f = slip_weakening("time_scale");
  f.t_star = 0.01;
  f.update = StrengthUpdate::exponential;
  const StrengthLaw law(f);
  const double p0 = 100.0, p1 = 50.0, dt = 0.002;
  FrictionState state = law.resting_state(f, p0);
  const FrictionStep step = law.advance(f, state, p0, p1, 0.5, dt);
  const double filtered = 0.677 * p1 + (0.677 * p0 - 0.677 * p1) * std::exp(-dt / f.t_star);
  EXPECT_NEAR(step.state.filtered, filtered, 1e-12 * filtered);
  const double mu = 0.677 - (0.677 - 0.525) * (0.5 * dt / 0.4);
  EXPECT_NEAR(step.strength, mu / 0.677 * filtered, 1e-12 * filtered);
}

TEST(FrictionLaws, ConstantCoefficientStrengthIsTheFilteredStateExactly) {
  // For a constant mu the strength is c* to the bit (mu / mu = 1), so the paper's law is
  // unchanged by the state c* = mu_0 sigma*.
  for (const char* kind : {"prakash_clifton", "coulomb"}) {
    Friction f;
    f.law = kind;
    const StrengthLaw law(f);
    FrictionState state{0.0112345678901234, 3.0};
    for (double mu : {0.75, 0.1, 1.7e-3, 123.456}) {
      f.mu = mu;
      EXPECT_EQ(law.strength(f, state), state.filtered) << kind << " mu " << mu;
    }
  }
  Friction zero;
  zero.mu = 0.0;
  EXPECT_EQ(StrengthLaw(zero).strength(zero, {0.0, 1.0}), 0.0); // not 0/0
}

TEST(FrictionLaws, EachLawNamesTheValuesItUses) {
  auto uses = [](Friction f, double FrictionValues::*member) {
    return StrengthLaw(f).uses(member);
  };
  Friction pc; // prakash_clifton: mu, L, v_star
  EXPECT_TRUE(uses(pc, &FrictionValues::mu));
  EXPECT_TRUE(uses(pc, &FrictionValues::L));
  EXPECT_TRUE(uses(pc, &FrictionValues::v_star));
  EXPECT_FALSE(uses(pc, &FrictionValues::t_star));
  EXPECT_FALSE(uses(pc, &FrictionValues::mu_s));
  Friction coulomb;
  coulomb.law = "coulomb"; // plain: mu only
  EXPECT_TRUE(uses(coulomb, &FrictionValues::mu));
  EXPECT_FALSE(uses(coulomb, &FrictionValues::L));
  coulomb.regularization = "time_scale";
  EXPECT_TRUE(uses(coulomb, &FrictionValues::t_star));
  const Friction sw = slip_weakening("slip_scale");
  for (auto m : {&FrictionValues::mu_s, &FrictionValues::mu_d, &FrictionValues::D_c,
                 &FrictionValues::L, &FrictionValues::v_star})
    EXPECT_TRUE(uses(sw, m));
  EXPECT_FALSE(uses(sw, &FrictionValues::mu));
  EXPECT_EQ(std::string(effective_regularization(pc).description().name), "slip_scale");
  EXPECT_EQ(find_coefficient_law("slip_weakening"), &coefficient_law(sw));
  EXPECT_EQ(find_coefficient_law("no such law"), nullptr);
  EXPECT_NE(find_regularization_law("time_scale"), nullptr);
}

TEST(FrictionLaws, TimeScaleIsNotPrakashClifton) {
  // The same state and step: the slip scale relaxes faster the faster the node slips, the
  // time scale does not depend on the slip speed at all.
  Friction pc;
  pc.L = 1e-3;
  Friction ts;
  ts.law = "coulomb";
  ts.regularization = "time_scale";
  ts.t_star = pc.L / pc.v_star; // the same rate at rest
  const FrictionState start{0.75 * 0.015, 0.0};
  auto after = [&](const Friction& f, double speed) {
    return StrengthLaw(f).advance(f, start, 0.015, 0.0075, speed, 0.01).strength;
  };
  EXPECT_EQ(after(ts, 0.0), after(ts, 1.0));
  EXPECT_DOUBLE_EQ(after(pc, 0.0), after(ts, 0.0)); // equal rates at rest
  EXPECT_LT(after(pc, 1.0), after(pc, 0.0) - 1e-4); // PC follows the drop much faster
}

} // namespace
} // namespace slipfront
