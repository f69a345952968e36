// The per-node interface parameters (solver/interface/interface_parameters.hpp): the uniform
// values, then the profiles in order (closed intervals, `outside` strict), then the
// overstressed patch; the nodes a check must visit; and the resting state they give.
#include "solver/interface/interface_parameters.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

SimulationParams with_profiles() {
  SimulationParams p;
  p.friction.law = "slip_weakening";
  Profile barrier; // mu_s = 10 beyond |x1| > 3
  barrier.x1_min = -3.0;
  barrier.x1_max = 3.0;
  barrier.outside = true;
  barrier.friction = {{&FrictionValues::mu_s, 10.0}};
  Profile band; // then, on [2, 5]: another shear and normal stress
  band.x1_min = 2.0;
  band.x1_max = 5.0;
  band.shear_stress = 0.008;
  band.normal_stress = -0.02;
  p.profiles = {barrier, band};
  return p;
}

TEST(InterfaceParameters, ProfilesApplyInOrderOnClosedIntervals) {
  const SimulationParams p = with_profiles();
  auto at = [&](double x1) { return node_parameters(p, x1); };
  EXPECT_EQ(at(0.0).friction.mu_s, p.friction.mu_s); // inside the barrier's interval
  EXPECT_EQ(at(0.0).shear_stress, p.loading.shear_stress);
  EXPECT_EQ(at(0.0).shear_source, uniform_source);
  EXPECT_EQ(at(3.0).friction.mu_s, p.friction.mu_s); // the end is inside: outside is strict
  EXPECT_EQ(at(3.0 + 1e-12).friction.mu_s, 10.0);
  EXPECT_EQ(at(-3.5).friction.mu_s, 10.0);
  EXPECT_EQ(at(-3.5).friction_source(&FrictionValues::mu_s), 0);
  EXPECT_EQ(at(-3.5).friction_source(&FrictionValues::mu_d), uniform_source);
  EXPECT_EQ(at(2.0).shear_stress, 0.008); // closed: both ends belong to [2, 5]
  EXPECT_EQ(at(5.0).normal_stress, -0.02);
  EXPECT_EQ(at(5.0).shear_source, 1);
  EXPECT_EQ(at(4.0).friction.mu_s, 10.0); // both entries: each sets its own values
  EXPECT_EQ(at(4.0).normal_source, 1);
  EXPECT_EQ(at(5.5).normal_stress, p.loading.normal_stress);
}

TEST(InterfaceParameters, TheOverstressedPatchComesLast) {
  SimulationParams p = with_profiles();
  p.nucleation.type = NucleationType::overstressed_patch;
  p.nucleation.x1_min = 4.0;
  p.nucleation.x1_max = 6.0;
  p.nucleation.shear_stress = 0.03;
  EXPECT_EQ(node_parameters(p, 4.5).shear_stress, 0.03); // over the band's 0.008
  EXPECT_EQ(node_parameters(p, 4.5).shear_source, patch_source);
  EXPECT_EQ(node_parameters(p, 4.5).normal_stress, -0.02); // the band's still
  EXPECT_EQ(node_parameters(p, 6.5).shear_stress, p.loading.shear_stress);
  p.nucleation.enabled = false; // no nucleation of any type: no patch
  EXPECT_EQ(node_parameters(p, 4.5).shear_stress, 0.008);
}

TEST(InterfaceParameters, RepresentativeNodesSeeEveryValue) {
  SimulationParams p = with_profiles();
  p.nucleation.type = NucleationType::overstressed_patch;
  const int nx = 1600;
  const double dx = 0.025;
  const InterfaceParameters all = interface_parameters(p, nx, dx);
  const std::vector<int> nodes = representative_nodes(p, nx, dx);
  EXPECT_LT(nodes.size(), 40u);
  // Every node has the parameters of the nearest representative node at or before it (the
  // first node of each stretch is one).
  for (int i = 0, k = 0; i < nx; ++i) {
    while (k + 1 < int(nodes.size()) && nodes[k + 1] <= i)
      ++k;
    const int r = nodes[k];
    ASSERT_TRUE(all.shear_stress[r] == all.shear_stress[i] &&
                all.normal_stress[r] == all.normal_stress[i] &&
                all.friction[r].mu_s == all.friction[i].mu_s)
        << "node " << i << " at x1 = " << all.x1[i] << ", representative " << r;
  }
  EXPECT_EQ(representative_nodes(SimulationParams{}, nx, dx), (std::vector<int>{0, nx - 1}));
}

TEST(InterfaceParameters, RestingStateHoldsTheNodesStressesAndStaticStrength) {
  SimulationParams p = with_profiles();
  const InterfaceParameters all = interface_parameters(p, 400, 0.1);
  const StrengthLaw law(p.friction);
  const InterfaceFields f = resting_interface(all, law);
  for (int i = 0; i < 400; ++i) {
    EXPECT_EQ(f.x1[i], p.geometry.x_min + i * 0.1);
    EXPECT_EQ(f.shear_traction[i], all.shear_stress[i]);
    EXPECT_EQ(f.pressure[i], std::abs(all.normal_stress[i]));
    EXPECT_EQ(f.strength[i], all.friction[i].mu_s * std::abs(all.normal_stress[i]));
    EXPECT_EQ(f.velocity[i], 0.0);
  }
}

} // namespace
} // namespace slipfront
