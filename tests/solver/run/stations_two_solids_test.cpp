// Stations on the interface between two elastic solids (spectral BI with a lower half-space,
// docs/spectral-bi.md "Two half-spaces"): the station recorder reads the interface fields the
// time loop has, which with two solids are the relative motion (slip and slip rate of the
// upper solid minus the lower) and the tractions between them. So a station on a node reads
// the node's sampled interface values bit for bit at every step, a station between two nodes
// their weighted sum, and the rupture time is read from that relative slip rate, as on the
// rigid plane; and the lower solid does change what a station records.
#include "verification_support.hpp"

#include "solver/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

// A Coulomb rupture driven by a shear pulse around x1 = 0 on [-10, 10) at n_d = 10 (dx =
// 0.1 m), the lower solid the upper's material (well-posed with Coulomb friction: no
// slip-induced normal stress), stations on a node (0) and halfway between two (1.05) inside the
// pulse, where the interface slides, and one far away (9.5), where it stays stuck.
SimulationParams two_solid_scene() {
  SimulationParams p = verification::small_block(20.0, 1.0, 10.0);
  p.geometry.x_min = -10.0;
  p.method = Method::spectral_bi;
  p.lower.side = LowerSide::elastic;
  p.lower.material = p.material;
  p.friction.law = "coulomb";
  p.spectral.time_step_factor = 0.25;
  p.time.duration = 2.0;
  p.extra_load = [](double x1, double) {
    return InterfaceTraction{std::abs(x1) <= 1.5 ? 0.004 : 0.0, 0.0};
  };
  p.stations.x1 = {0.0, 1.05, 9.5};
  return p;
}

struct Recorded {
  RunResult result;
  verification::RecordingSink sink;
};

void run(const SimulationParams& p, Recorded& r) {
  RunHooks hooks;
  hooks.sink = &r.sink;
  r.result = run_simulation(p, hooks);
}

TEST(StationsTwoSolids, ReadTheRelativeInterfaceFieldsEveryStep) {
  Recorded two;
  run(two_solid_scene(), two);
  const StationRecords& s = two.result.stations;
  const auto& samples = two.sink.samples;
  ASSERT_EQ(s.time.size(), samples.size()); // the interface sampled at every step
  ASSERT_GT(samples.size(), 10u);
  const std::vector<double>& x1 = two.sink.layout.x1;
  const auto node = [&](double x) {
    return std::size_t(std::lround((x - x1.front()) / (x1[1] - x1[0])));
  };
  const std::size_t on = node(0.0), left = node(1.0), right = node(1.1), n = s.x1.size();
  // x_min + 100 dx is 5.6e-16 in binary: the station at 0 is on that node, weights 1 and 0.
  ASSERT_NEAR(x1[on], 0.0, 1e-12);
  ASSERT_EQ(s.node_weight[1], 0.0);
  double largest_slip = 0.0;
  for (std::size_t k = 0; k < samples.size(); ++k) {
    const InterfaceSample& f = samples[k];
    ASSERT_EQ(s.time[k], f.time);
    EXPECT_EQ(s.slip_rate[k * n], f.slip_velocity[on]);
    EXPECT_EQ(s.slip[k * n], f.slip[on]);
    EXPECT_EQ(s.shear_traction[k * n], f.shear_traction[on]);
    EXPECT_EQ(s.normal_traction[k * n], 0.0 - f.contact_pressure[on]);
    const double between = 0.5 * f.slip[left] + 0.5 * f.slip[right];
    EXPECT_NEAR(s.slip[k * n + 1], between, 1e-14 * std::max(1.0, std::abs(between)));
    largest_slip = std::max(largest_slip, std::abs(f.slip[on]));
  }
  EXPECT_GT(largest_slip, 0.0); // the interface slid at the first station
  EXPECT_FALSE(std::isnan(s.rupture_time[1]));
  EXPECT_EQ(s.rupture_time[0], s.time[0]);    // the pulse slides the interface at once
  EXPECT_TRUE(std::isnan(s.rupture_time[2])); // stuck, 9.5 m away
}

TEST(StationsTwoSolids, TheLowerSolidChangesWhatAStationRecords) {
  SimulationParams p = two_solid_scene();
  SimulationParams rigid = p;
  rigid.lower.side = LowerSide::rigid;
  Recorded two, one;
  run(p, two);
  run(rigid, one);
  ASSERT_EQ(two.result.stations.time, one.result.stations.time); // the same steps
  const std::size_t last = (two.result.stations.time.size() - 1) * p.stations.x1.size();
  // The lower solid moves too (the opposite way): the relative slip at x1 = 0 is larger than
  // the slip of the same solid on the rigid plane.
  EXPECT_GT(two.result.stations.slip[last], 1.05 * one.result.stations.slip[last]);
}

} // namespace
} // namespace slipfront
