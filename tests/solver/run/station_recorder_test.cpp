// The station recorder (solver/run/station_recorder.hpp) on synthetic interfaces: the values
// between two nodes and on a node, across the periodic seam, the sign of the normal traction,
// the rupture time, and nothing recorded without stations.
#include "solver/run/station_recorder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slipfront {
namespace {

constexpr double kX0 = -1.0; // x_min
constexpr double kDx = 0.1;
constexpr int kNx = 8; // nodes at -1.0, -0.9, ..., -0.3; the domain ends at -0.2

// Node values that no linear formula reproduces by accident: a value read "exactly" is the
// node's own bits.
double value_at(int node, int field) {
  return std::sqrt(2.0 + node) * (field + 1) + 1.0 / (3.0 + node);
}

InterfaceFields synthetic_interface() {
  InterfaceFields f;
  for (int i = 0; i < kNx; ++i) {
    f.x1.push_back(kX0 + i * kDx);
    f.velocity.push_back(value_at(i, 0));
    f.slip.push_back(value_at(i, 1));
    f.shear_traction.push_back(value_at(i, 2));
    f.pressure.push_back(value_at(i, 3));
  }
  f.half_velocity = f.velocity;
  f.opening.assign(kNx, 0.0);
  f.strength.assign(kNx, 0.0);
  f.state.assign(kNx, std::int8_t(NodeState::stick));
  return f;
}

Stations stations_at(std::vector<double> x1, double threshold = 1e-3) {
  Stations s;
  s.x1 = std::move(x1);
  s.rupture_threshold = threshold;
  return s;
}

TEST(StationRecorder, InterpolatesLinearlyBetweenTheTwoNodesAround) {
  // x1 = -0.675 lies between node 3 (-0.7) and node 4 (-0.6), a quarter of the way.
  StationRecorder recorder(stations_at({-0.675}), kX0, kDx, kNx, 10);
  recorder.record(synthetic_interface(), 0.0);
  const StationRecords& r = recorder.records();
  ASSERT_EQ(r.time.size(), 1u);
  EXPECT_DOUBLE_EQ(r.node_x1[0], kX0 + 3 * kDx);
  EXPECT_DOUBLE_EQ(r.node_x1[1], kX0 + 4 * kDx);
  EXPECT_NEAR(r.node_weight[0], 0.75, 1e-12);
  EXPECT_NEAR(r.node_weight[1], 0.25, 1e-12);
  auto between = [](int field) { return 0.75 * value_at(3, field) + 0.25 * value_at(4, field); };
  EXPECT_NEAR(r.slip_rate[0], between(0), 1e-12);
  EXPECT_NEAR(r.slip[0], between(1), 1e-12);
  EXPECT_NEAR(r.shear_traction[0], between(2), 1e-12);
  EXPECT_NEAR(r.normal_traction[0], -between(3), 1e-12); // -p: negative in compression
}

TEST(StationRecorder, OnANodeIsThatNodeExactly) {
  // Node 2 is at -1.0 + 2 * 0.1 = -0.8, but (x1 - x_min) / dx is 1.9999999999999996 in
  // binary for both spellings of the position: both must read node 2's own values.
  const double computed = kX0 + 2 * kDx, written = -0.8;
  StationRecorder recorder(stations_at({computed, written, kX0}), kX0, kDx, kNx, 10);
  recorder.record(synthetic_interface(), 0.0);
  const StationRecords& r = recorder.records();
  for (int s = 0; s < 2; ++s) {
    EXPECT_EQ(r.node_weight[2 * s], 1.0);
    EXPECT_EQ(r.node_weight[2 * s + 1], 0.0);
    EXPECT_EQ(r.node_x1[2 * s], kX0 + 2 * kDx);
    EXPECT_EQ(r.slip_rate[s], value_at(2, 0));
    EXPECT_EQ(r.slip[s], value_at(2, 1));
    EXPECT_EQ(r.shear_traction[s], value_at(2, 2));
    EXPECT_EQ(r.normal_traction[s], -value_at(2, 3));
  }
  EXPECT_EQ(r.slip_rate[2], value_at(0, 0)); // the first node, x_min itself
}

TEST(StationRecorder, AnOpenNodeHasZeroNormalTractionNotMinusZero) {
  // p = 0 where the interface is open: the traction is 0, and the CSV writes "0", not "-0".
  StationRecorder recorder(stations_at({kX0 + 5 * kDx}), kX0, kDx, kNx, 10);
  InterfaceFields f = synthetic_interface();
  f.pressure[5] = 0.0;
  recorder.record(f, 0.0);
  EXPECT_EQ(recorder.records().normal_traction[0], 0.0);
  EXPECT_FALSE(std::signbit(recorder.records().normal_traction[0]));
}

TEST(StationRecorder, ThePeriodicSeamJoinsTheLastNodeToTheFirst) {
  // x1 = -0.24 lies between the last node (-0.3) and x_min + width = -0.2, which is node 0.
  StationRecorder recorder(stations_at({-0.24}), kX0, kDx, kNx, 10);
  recorder.record(synthetic_interface(), 0.0);
  const StationRecords& r = recorder.records();
  EXPECT_DOUBLE_EQ(r.node_x1[0], kX0 + 7 * kDx);
  EXPECT_DOUBLE_EQ(r.node_x1[1], kX0); // node 0 again
  EXPECT_NEAR(r.slip[0], 0.4 * value_at(7, 1) + 0.6 * value_at(0, 1), 1e-12);
}

TEST(StationRecorder, RuptureTimeIsTheFirstCrossingInterpolatedInTime) {
  // Station 0 on node 2, station 1 between nodes 2 and 3 (V there: half of node 2's).
  const double dt = 0.01;
  StationRecorder recorder(stations_at({kX0 + 2 * kDx, kX0 + 2.5 * kDx}, 1e-3), kX0, kDx, kNx, 10);
  InterfaceFields f = synthetic_interface();
  f.velocity.assign(kNx, 0.0);
  const double node2_speed[] = {0.0, 4e-4, -8e-4, -1.2e-3, 5e-4, 3e-3}; // |V| crosses at step 3
  for (int n = 0; n < 6; ++n) {
    f.velocity[2] = node2_speed[n];
    recorder.record(f, n * dt);
  }
  const StationRecords& r = recorder.records();
  ASSERT_EQ(r.time.size(), 6u);
  EXPECT_EQ(r.time[5], 5 * dt);
  // |V| = 8e-4 at step 2 and 1.2e-3 at step 3: the threshold halfway between.
  EXPECT_NEAR(r.rupture_time[0], 2.5 * dt, 1e-15);
  // Station 1 sees half: 6e-4 at step 3, 2.5e-4 at step 4, 1.5e-3 at step 5: crossing at
  // 4 + (1e-3 - 2.5e-4) / (1.5e-3 - 2.5e-4) = 4.6 steps; later excursions do not move it.
  EXPECT_NEAR(r.rupture_time[1], 4.6 * dt, 1e-15);
}

TEST(StationRecorder, RuptureTimeAtTheFirstStepOrNever) {
  StationRecorder recorder(stations_at({kX0, kX0 + kDx}, 0.5), kX0, kDx, kNx, 10);
  InterfaceFields f = synthetic_interface();
  f.velocity.assign(kNx, 0.0);
  f.velocity[0] = 0.75; // above the threshold at t_0 already
  recorder.record(f, 0.0);
  recorder.record(f, 0.1);
  EXPECT_EQ(recorder.records().rupture_time[0], 0.0);
  EXPECT_TRUE(std::isnan(recorder.records().rupture_time[1]));
}

TEST(StationRecorder, WithoutStationsRecordsNothing) {
  StationRecorder recorder(Stations{}, kX0, kDx, kNx, 1000);
  recorder.record(synthetic_interface(), 0.0);
  const StationRecords r = recorder.take();
  EXPECT_TRUE(r.empty());
  EXPECT_TRUE(r.time.empty());
  EXPECT_TRUE(r.slip_rate.empty());
  EXPECT_EQ(StationRecorder::record_bytes(Stations{}, 1e6), 0.0);
}

TEST(StationRecorder, RecordBytesCountTimeAndFourSeriesPerStep) {
  const Stations two = stations_at({0.0, 1.0});
  // 8 bytes x 1000 steps x (time + 4 series x 2 stations), plus 5 doubles per station.
  EXPECT_EQ(StationRecorder::record_bytes(two, 1000.0), 8.0 * 1000.0 * 9.0 + 8.0 * 5.0 * 2.0);
}

} // namespace
} // namespace slipfront
