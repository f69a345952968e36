// The split-node law between two deformable solids (solver/interface/split_node.hpp): the
// rigid lower side is the single-node law bit for bit; momentum is kept in every state; a
// stuck pair has one tangential velocity; a closed pair's gap closes; a slipping pair carries
// the strength; and a lower side ever heavier tends to the rigid plane.
#include "solver/interface/split_node.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

InterfaceNodeConstants constants() {
  InterfaceNodeConstants c;
  c.dt = 0.1;
  c.tributary_length = 0.5;
  Friction coulomb;
  coulomb.law = "coulomb";
  c.law = StrengthLaw(coulomb);
  return c;
}

// Friction values with the coefficient mu.
FrictionValues with_mu(double mu) {
  FrictionValues values;
  values.mu = mu;
  return values;
}

// The last step's strength as the friction state (a constant coefficient: strength = c*).
FrictionState strength_state(double strength) {
  return {strength, 0.0};
}

const InterfaceSide upper_side{2.0, 5.0, 0.03, -0.02};
const InterfaceSide lower_side{3.0, 4.0, -0.01, 0.015};

// Total momentum of the pair along x1 and x2.
double momentum1(const InterfaceSide& a, const InterfaceSide& b) {
  return a.mass1 * a.v1 + b.mass1 * b.v1;
}
double momentum2(const InterfaceSide& a, const InterfaceSide& b) {
  return a.mass2 * a.v2 + b.mass2 * b.v2;
}

TEST(SplitNode, RigidLowerSideIsTheSingleNodeLawBitForBit) {
  InterfaceNodeConstants c = constants();
  c.mass1 = upper_side.mass1;
  c.mass2 = upper_side.mass2;
  for (double gap : {0.0, 1e-4, 5e-3}) {
    const InterfaceNodeStep single = resolve_interface_node(
        c, with_mu(0.5), gap, upper_side.v1, upper_side.v2, 0.01, strength_state(0.3), 0.6);
    const SplitNodeStep pair = resolve_split_node(constants(), with_mu(0.5), gap, upper_side,
                                                  lower_side, true, 0.01, strength_state(0.3), 0.6);
    EXPECT_EQ(pair.relative.contact_force1, single.contact_force1);
    EXPECT_EQ(pair.relative.contact_force2, single.contact_force2);
    EXPECT_EQ(pair.relative.pressure, single.pressure);
    EXPECT_EQ(pair.relative.strength, single.strength);
    EXPECT_EQ(pair.relative.state, single.state);
    EXPECT_EQ(pair.upper.v1, single.v1);
    EXPECT_EQ(pair.upper.v2, single.v2);
    EXPECT_EQ(pair.lower.v1, 0.0);
    EXPECT_EQ(pair.lower.v2, 0.0);
  }
}

TEST(SplitNode, MomentumIsKeptAndTheForceActsOnBothSides) {
  // Closing (gap 0, sides approaching), stuck or slipping by the strength, and opening.
  for (double mu : {0.05, 0.5, 50.0}) {
    const InterfaceNodeConstants c = constants();
    for (double v2_lower : {0.015, -0.05}) {
      InterfaceSide lower = lower_side;
      lower.v2 = v2_lower;
      const SplitNodeStep r = resolve_split_node(c, with_mu(mu), 0.0, upper_side, lower, false, 0.0,
                                                 strength_state(0.0), 0.0);
      EXPECT_NEAR(momentum1(r.upper, r.lower), momentum1(upper_side, lower), 1e-15);
      EXPECT_NEAR(momentum2(r.upper, r.lower), momentum2(upper_side, lower), 1e-15);
      // The upper side's change is dt C / m+ (C the force the law reports).
      EXPECT_NEAR(r.upper.v1 - upper_side.v1, c.dt * r.relative.contact_force1 / upper_side.mass1,
                  1e-15);
      EXPECT_NEAR(r.upper.v2 - upper_side.v2, c.dt * r.relative.contact_force2 / upper_side.mass2,
                  1e-15);
    }
  }
}

TEST(SplitNode, AStuckPairMovesWithOneVelocityAndAClosedPairClosesItsGap) {
  InterfaceNodeConstants c = constants();
  const double gap = 2e-4;
  const SplitNodeStep r = resolve_split_node(c, with_mu(50.0), gap, upper_side, lower_side, false,
                                             0.0, strength_state(0.0), 0.0); // mu 50 holds all
  ASSERT_EQ(r.relative.state, NodeState::stick);
  EXPECT_EQ(r.upper.v1, r.lower.v1); // exactly
  EXPECT_DOUBLE_EQ(r.upper.v1, (2.0 * 0.03 + 3.0 * -0.01) / 5.0);
  EXPECT_NEAR(gap + c.dt * (r.upper.v2 - r.lower.v2), 0.0, 1e-18);
  // The pressure: the reaction that closes the gap, through the effective mass 5*4/9.
  const double m_eff = 5.0 * 4.0 / 9.0;
  const double reaction = -m_eff * (gap + c.dt * (upper_side.v2 - lower_side.v2)) / (c.dt * c.dt);
  EXPECT_DOUBLE_EQ(r.relative.pressure, reaction / c.tributary_length);
}

TEST(SplitNode, ASlippingPairCarriesTheStrengthAgainstTheRelativeSlip) {
  InterfaceNodeConstants c = constants();
  const SplitNodeStep r = resolve_split_node(c, with_mu(0.05), 0.0, upper_side, lower_side, false,
                                             0.0, strength_state(0.0), 0.0);
  ASSERT_EQ(r.relative.state, NodeState::slip);
  const double limit = r.relative.strength * c.tributary_length;
  EXPECT_DOUBLE_EQ(r.relative.contact_force1, -limit); // the upper side moves faster (+x1)
  EXPECT_GT(r.upper.v1 - r.lower.v1, 0.0);             // still slipping the same way
  EXPECT_DOUBLE_EQ(r.relative.v1, r.upper.v1 - r.lower.v1);
}

TEST(SplitNode, AnOpeningPairFeelsNoForce) {
  const SplitNodeStep r = resolve_split_node(constants(), with_mu(0.5), 1e-2, upper_side,
                                             lower_side, false, 0.0, strength_state(0.3), 0.6);
  ASSERT_EQ(r.relative.state, NodeState::open);
  EXPECT_EQ(r.upper.v1, upper_side.v1);
  EXPECT_EQ(r.upper.v2, upper_side.v2);
  EXPECT_EQ(r.lower.v1, lower_side.v1);
  EXPECT_EQ(r.lower.v2, lower_side.v2);
}

// The internal pair force F (FE: the initial contact force C0) is seen by the law but moves
// the sides only by C - F: a pre-stressed pair the interface holds stays exactly at rest, and
// with F the result is that of trial velocities holding -F (+F on the lower side).
TEST(SplitNode, AnInternalPairForceIsSeenByTheLawAndLeavesAHeldPairAtRest) {
  InterfaceNodeConstants c = constants();
  const PairForce c0{-0.2, 1.0}; // shear below mu * pressure: stuck
  const InterfaceSide up_rest{2.0, 5.0, 0.0, 0.0}, low_rest{3.0, 4.0, 0.0, 0.0};
  const SplitNodeStep held = resolve_split_node(c, with_mu(0.5), 0.0, up_rest, low_rest, false, 0.0,
                                                strength_state(0.0), 0.0, c0);
  ASSERT_EQ(held.relative.state, NodeState::stick);
  EXPECT_EQ(held.upper.v1, 0.0);
  EXPECT_EQ(held.upper.v2, 0.0);
  EXPECT_EQ(held.lower.v1, 0.0);
  EXPECT_EQ(held.lower.v2, 0.0);
  EXPECT_NEAR(held.relative.contact_force1, c0.f1, 1e-15);
  EXPECT_NEAR(held.relative.pressure * c.tributary_length, c0.f2, 1e-15);

  for (double mu : {0.05, 0.5}) { // slipping and stuck, and opening (gap 1e-2)
    for (double gap : {0.0, 1e-2}) {
      InterfaceSide up_with = upper_side, low_with = lower_side;
      up_with.v1 -= c.dt * c0.f1 / up_with.mass1;
      up_with.v2 -= c.dt * c0.f2 / up_with.mass2;
      low_with.v1 += c.dt * c0.f1 / low_with.mass1;
      low_with.v2 += c.dt * c0.f2 / low_with.mass2;
      const SplitNodeStep a = resolve_split_node(c, with_mu(mu), gap, upper_side, lower_side, false,
                                                 0.0, strength_state(0.3), 0.6, c0);
      const SplitNodeStep b = resolve_split_node(c, with_mu(mu), gap, up_with, low_with, false, 0.0,
                                                 strength_state(0.3), 0.6);
      EXPECT_EQ(a.relative.state, b.relative.state);
      EXPECT_NEAR(a.relative.contact_force1, b.relative.contact_force1, 1e-14);
      EXPECT_NEAR(a.relative.contact_force2, b.relative.contact_force2, 1e-14);
      EXPECT_NEAR(a.upper.v1, b.upper.v1, 1e-15);
      EXPECT_NEAR(a.upper.v2, b.upper.v2, 1e-15);
      EXPECT_NEAR(a.lower.v1, b.lower.v1, 1e-15);
      EXPECT_NEAR(a.lower.v2, b.lower.v2, 1e-15);
    }
  }
}

TEST(SplitNode, AHeavierAndHeavierLowerSideAtRestTendsToTheRigidPlane) {
  const SplitNodeStep rigid = resolve_split_node(constants(), with_mu(0.5), 1e-4, upper_side,
                                                 lower_side, true, 0.0, strength_state(0.0), 0.0);
  double last_error = INFINITY;
  for (double scale : {1e2, 1e4, 1e6, 1e8}) {
    const InterfaceSide heavy{lower_side.mass1 * scale, lower_side.mass2 * scale, 0.0, 0.0};
    const SplitNodeStep r = resolve_split_node(constants(), with_mu(0.5), 1e-4, upper_side, heavy,
                                               false, 0.0, strength_state(0.0), 0.0);
    const double error = std::abs(r.relative.contact_force2 - rigid.relative.contact_force2) +
                         std::abs(r.relative.contact_force1 - rigid.relative.contact_force1) +
                         std::abs(r.upper.v1 - rigid.upper.v1);
    EXPECT_LT(error, last_error);
    EXPECT_LT(error, 10.0 / scale); // first order in m+/m-
    last_error = error;
  }
}

} // namespace
} // namespace slipfront
