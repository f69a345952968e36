// The summary of a station's series (solver/run/station_summary.hpp) on synthetic records: the
// crossing of any threshold, linear between steps, the same as the recorder's at its own; the
// peak slip rate and its first time, whatever the sign of V; the final slip; NaN without steps.
#include "solver/run/station_summary.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

// Two stations over five steps of 0.1 s: the first slips forwards, the second backwards.
StationRecords two_stations() {
  StationRecords r;
  r.x1 = {0.0, 5.0};
  r.rupture_threshold = 0.1;
  r.time = {0.0, 0.1, 0.2, 0.3, 0.4};
  // Row-major [time, station].
  r.slip_rate = {0.001, -0.001, 0.05, -0.02, 0.25, -0.4, 1.5, -0.3, 0.75, -3.0};
  r.slip = {0.0, 0.0, 0.01, -0.01, 0.03, -0.05, 0.2, -0.1, 0.3, -0.4};
  r.rupture_time = {0.12, 0.1 + 0.1 * (0.1 - 0.02) / (0.4 - 0.02)};
  return r;
}

TEST(StationSummary, CrossingPeakAndFinalSlip) {
  const StationRecords r = two_stations();
  const StationSummary first = summarize_station(r, 0, 0.1);
  // |V| from 0.05 at 0.1 s to 0.25 at 0.2 s: 0.1 is crossed a quarter of the way.
  EXPECT_NEAR(first.rupture_time, 0.125, 1e-15);
  EXPECT_EQ(first.peak_slip_rate, 1.5);
  EXPECT_EQ(first.peak_time, 0.3);
  EXPECT_EQ(first.final_slip, 0.3);
  const StationSummary second = summarize_station(r, 1, 0.1);
  EXPECT_NEAR(second.rupture_time, r.rupture_time[1], 1e-15) << "the recorder's own crossing";
  EXPECT_EQ(second.peak_slip_rate, 3.0) << "|V| of a backward slip";
  EXPECT_EQ(second.peak_time, 0.4);
  EXPECT_EQ(second.final_slip, -0.4);
}

TEST(StationSummary, AnotherThresholdAndNeverAndNoSteps) {
  const StationRecords r = two_stations();
  // 0.01 m/s: the first station crosses between 0.001 (0 s) and 0.05 (0.1 s).
  EXPECT_NEAR(summarize_station(r, 0, 0.01).rupture_time, 0.1 * (0.01 - 0.001) / (0.05 - 0.001),
              1e-15);
  // Above at the first step: that step's time.
  EXPECT_EQ(summarize_station(r, 0, 1e-4).rupture_time, 0.0);
  EXPECT_TRUE(std::isnan(summarize_station(r, 0, 10.0).rupture_time)) << "never";
  StationRecords empty = r;
  empty.time.clear();
  const StationSummary none = summarize_station(empty, 0, 0.1);
  EXPECT_TRUE(std::isnan(none.peak_slip_rate) && std::isnan(none.final_slip));
}

} // namespace
} // namespace slipfront
