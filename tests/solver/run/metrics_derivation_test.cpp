// The metric derivations of a run (solver/run/metrics.hpp) on hand-made records: nodal lookup
// on the periodic line, the front metrics, the energy-balance error.
#include "solver/run/energy_recorder.hpp"
#include "solver/run/front_metrics.hpp"
#include "solver/run/periodic_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slipfront {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

TEST(PeriodicIndex, WrapsBothWays) {
  EXPECT_EQ(periodic_index(0, 5), 0);
  EXPECT_EQ(periodic_index(7, 5), 2);
  EXPECT_EQ(periodic_index(-1, 5), 4);
  EXPECT_EQ(periodic_index(-11, 5), 4);
}

TEST(NodalLookup, NearestNodeAndLinearInterpolationWrapAround) {
  EXPECT_EQ(nearest_node(2.2, 0.0, 0.5, 10), 4);
  EXPECT_EQ(nearest_node(4.8, 0.0, 0.5, 10), 0);
  EXPECT_EQ(nearest_node(-0.6, 0.0, 0.5, 10), 9);
  const std::vector<double> v = {0.0, 1.0, 2.0, 3.0};
  EXPECT_DOUBLE_EQ(interpolate_nodal(v, 1.25, 0.0, 1.0), 1.25);
  EXPECT_DOUBLE_EQ(interpolate_nodal(v, 3.5, 0.0, 1.0), 1.5); // between node 3 and node 0
  EXPECT_EQ(interpolate_nodal(v, 2.0, 0.0, 1.0), 2.0);
  EXPECT_TRUE(std::isnan(interpolate_nodal({0.0, kNaN}, 0.5, 0.0, 1.0)));
}

TEST(EnergyBalanceError, RelativeMismatchAtTheLastRecord) {
  EnergyRecords e;
  EXPECT_EQ(energy_balance_error(e), 0.0); // nothing recorded
  e.time = {0.0, 1.0};
  e.kinetic = {0.0, 2.0};
  e.strain = {0.0, 3.0};
  e.external_work = {0.0, 10.0};
  e.dissipated = {0.0, 4.0};
  // stored 5, net 6: |5 - 6| / max(|W| = 10, 5).
  EXPECT_DOUBLE_EQ(energy_balance_error(e), 0.1);
}

TEST(FrontMetrics, ArrestPositionSpeedAndOutcomeOfALinearFront) {
  SimulationParams p;
  p.geometry.x_min = 0.0;
  p.geometry.width = 20.0;
  p.nucleation.enabled = false;
  p.probes.arrival_x1 = 5.25;
  const double dx = 0.5;
  std::vector<double> arrival(40, kNaN);
  for (int i = 4; i <= 24; ++i) // x1 = 2 .. 12 m at 2 m/s
    arrival[i] = (i * dx - 2.0) / 2.0;
  FrontProfile front;
  Metrics m;
  m.outcome = Outcome::arrested;
  derive_front_metrics(p, dx, arrival, front, m);
  EXPECT_EQ(front.x1.size(), 40u);
  EXPECT_EQ(m.arrest_position, 12.0);
  EXPECT_EQ(m.propagation_distance, 10.0);
  EXPECT_DOUBLE_EQ(m.arrival_time_at_probe, 1.625);
  EXPECT_NEAR(m.max_rupture_speed, 2.0, 1e-9);
  EXPECT_NEAR(m.mean_rupture_speed, 2.0, 1e-9);
  EXPECT_EQ(m.outcome, Outcome::arrested);
  EXPECT_TRUE(m.warnings.empty());

  Metrics none;
  derive_front_metrics(p, dx, std::vector<double>(40, kNaN), front, none);
  EXPECT_TRUE(std::isnan(none.arrest_position));
  EXPECT_EQ(none.outcome, Outcome::no_rupture);
}

} // namespace
} // namespace slipfront
