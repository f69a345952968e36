// The interface law of one node (solver/interface/interface_law.hpp) with a different mass along x1
// and x2 (as the boundary-integral method uses it): contact, stick, slip and opening.
#include "solver/interface/interface_law.hpp"

#include <gtest/gtest.h>

namespace slipfront {
namespace {

Friction coulomb() {
  Friction f;
  f.law = "coulomb";
  f.mu = 0.5;
  return f;
}

InterfaceNodeConstants constants(const Friction& friction = coulomb()) {
  InterfaceNodeConstants c;
  c.mass1 = 2.0;
  c.mass2 = 5.0;
  c.dt = 0.1;
  c.tributary_length = 0.5;
  c.law = StrengthLaw(friction);
  return c;
}

// The law with `friction`'s values; `strength`: the last step's (= c*, a constant mu).
InterfaceNodeStep resolve(const InterfaceNodeConstants& c, double u2, double v1_trial,
                          double v2_trial, double slip_speed, double strength,
                          double previous_pressure, const Friction& friction = coulomb()) {
  return resolve_interface_node(c, friction, u2, v1_trial, v2_trial, slip_speed,
                                FrictionState{strength, 0.0}, previous_pressure);
}

TEST(InterfaceLaw, ContactReactionClosesTheGapWithTheNormalMass) {
  const InterfaceNodeConstants c = constants();
  // u2 + dt v2_trial = 1e-3 - 0.1 * 0.02 = -1e-3: the plane pushes.
  const InterfaceNodeStep r = resolve(c, 1e-3, 0.0, -0.02, 0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(r.contact_force2, 5.0 * 1e-3 / (0.1 * 0.1));
  EXPECT_DOUBLE_EQ(r.pressure, r.contact_force2 / 0.5);
  EXPECT_DOUBLE_EQ(r.v2, -1e-3 / 0.1); // the next normal displacement is zero
  EXPECT_EQ(r.state, NodeState::stick);
  EXPECT_EQ(r.v1, 0.0);
}

TEST(InterfaceLaw, StickAndSlipUseTheTangentialMass) {
  const InterfaceNodeConstants c = constants();
  // Closed: p = 5 * 1e-3 / 0.01 / 0.5 = 1 Pa, Coulomb strength 0.5 Pa, limit 0.25 N/m.
  const InterfaceNodeStep stick = resolve(c, 0.0, 0.01, -0.01, 0.0, 0.0, 0.0);
  EXPECT_DOUBLE_EQ(stick.pressure, 1.0);
  EXPECT_DOUBLE_EQ(stick.strength, 0.5);
  EXPECT_EQ(stick.state, NodeState::stick);
  EXPECT_DOUBLE_EQ(stick.contact_force1, -2.0 * 0.01 / 0.1); // |-0.2| <= 0.25
  EXPECT_EQ(stick.v1, 0.0);

  const InterfaceNodeStep slip = resolve(c, 0.0, 0.05, -0.01, 0.0, 0.0, 0.0);
  EXPECT_EQ(slip.state, NodeState::slip); // stick force -1.0 exceeds 0.25
  EXPECT_DOUBLE_EQ(slip.contact_force1, -0.25);
  EXPECT_DOUBLE_EQ(slip.v1, 0.05 - 0.1 * 0.25 / 2.0);
}

TEST(InterfaceLaw, OpenNodeMovesFreely) {
  const InterfaceNodeConstants c = constants();
  const InterfaceNodeStep r = resolve(c, 1e-3, 0.3, 0.02, 0.0, 0.0, 0.0);
  EXPECT_EQ(r.state, NodeState::open);
  EXPECT_EQ(r.pressure, 0.0);
  EXPECT_EQ(r.contact_force1, 0.0);
  EXPECT_EQ(r.v1, 0.3);
  EXPECT_EQ(r.v2, 0.02);
}

TEST(InterfaceLaw, SlipSpeedDrivesTheStrengthUpdate) {
  Friction f = coulomb();
  f.law = "prakash_clifton";
  f.L = 1e-3;
  f.v_star = 1e-4;
  const InterfaceNodeConstants c = constants(f);
  const InterfaceNodeStep slow = resolve(c, 0.0, 0.0, -0.01, 0.0, 1.0, 1.0, f);
  const InterfaceNodeStep fast = resolve(c, 0.0, 0.0, -0.01, 0.01, 1.0, 1.0, f);
  // From tau_s = 1 towards mu p = 0.5: faster slip relaxes further.
  EXPECT_LT(fast.strength, slow.strength);
  EXPECT_GT(fast.strength, 0.5);
}

} // namespace
} // namespace slipfront
