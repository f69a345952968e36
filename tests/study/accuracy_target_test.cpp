// The accuracy target's decisions (api/study/accuracy_target.hpp, docs/studies-api.md
// "Accuracy target") on synthetic ladders whose exact answer is known.
#include "api/study/accuracy_target.hpp"

#include <gtest/gtest.h>

#include <cmath>

using nlohmann::json;
using namespace slipfront::api;

namespace {

const std::vector<double> ladder = {10, 20, 40, 80, 160};

StudyRun run_with(double n_d, const json& metrics, JobStatus status = JobStatus::succeeded) {
  json m = metrics;
  m["outcome"] = "arrested";
  return {"job" + std::to_string(static_cast<int>(n_d)), 5e-5, n_d, status, m, 0.5, 1e6};
}

// A first-order time metric: exact 9.05 s, error 0.25 / n_d.
StudyRun timed(double n_d) {
  return run_with(n_d, {{"arrival_time_at_probe", 9.05 - 0.25 / n_d}});
}

AccuracyTarget arrival(double tolerance) {
  return {"arrival_time_at_probe", tolerance, 5e-5};
}

} // namespace

TEST(AccuracyTarget, AsksForTheFirstMeshesThenWaits) {
  std::vector<StudyRun> runs;
  auto v = accuracy_verdict(arrival(1e-3), ladder, 0, 160, runs);
  EXPECT_EQ(v.state, AccuracyVerdict::State::run_next);
  EXPECT_DOUBLE_EQ(v.next_n_d, 10);
  runs.push_back(timed(10));
  runs.back().status = JobStatus::running;
  v = accuracy_verdict(arrival(1e-3), ladder, 0, 160, runs);
  EXPECT_EQ(v.state, AccuracyVerdict::State::waiting);
}

TEST(AccuracyTarget, StopsAtTheFirstMeshWhoseEstimateMeetsTheTarget) {
  // Changes 0.0125, 0.00625, 0.003125 s: relative 1.4e-3, 6.9e-4, 3.5e-4.
  std::vector<StudyRun> runs = {timed(10), timed(20)};
  auto v = accuracy_verdict(arrival(7e-4), ladder, 0, 160, runs);
  EXPECT_EQ(v.state, AccuracyVerdict::State::run_next);
  EXPECT_DOUBLE_EQ(v.next_n_d, 40);
  runs.push_back(timed(40));
  v = accuracy_verdict(arrival(7e-4), ladder, 0, 160, runs);
  ASSERT_EQ(v.state, AccuracyVerdict::State::met) << v.reason;
  EXPECT_DOUBLE_EQ(v.n_d, 40);
  EXPECT_EQ(v.estimate, "Richardson");
  EXPECT_NEAR(v.observed_order, 1.0, 1e-9);
  // Exact first order: the Richardson estimate is the true error, the extrapolation exact.
  EXPECT_NEAR(v.error, 0.25 / 40, 1e-12);
  EXPECT_NEAR(v.extrapolated, 9.05, 1e-12);
  EXPECT_EQ(v.steps.size(), 3u);
}

TEST(AccuracyTarget, TwoMeshesEstimateByTheirChange) {
  std::vector<StudyRun> runs = {timed(10), timed(20)};
  const auto v = accuracy_verdict(arrival(2e-3), ladder, 0, 160, runs);
  ASSERT_EQ(v.state, AccuracyVerdict::State::met);
  EXPECT_EQ(v.estimate, "last refinement");
  EXPECT_NEAR(v.error, 0.25 / 10 - 0.25 / 20, 1e-12);
  EXPECT_GE(v.error, std::abs(9.05 - v.value)); // first order at ratio 2: exactly the error
}

TEST(AccuracyTarget, NodeQuantisedMetricsNeverClaimLessThanTheNodeSpacing) {
  // The paper scene by BI: arrest_position 12.5 m at n_d 10 and 20 (the same node).
  std::vector<StudyRun> runs = {run_with(10, {{"arrest_position", 12.5}}),
                                run_with(20, {{"arrest_position", 12.5}})};
  const auto v = accuracy_verdict({"arrest_position", 0.005, 5e-5}, ladder, 0, 160, runs);
  ASSERT_EQ(v.state, AccuracyVerdict::State::met);
  EXPECT_EQ(v.estimate, "node spacing");
  EXPECT_DOUBLE_EQ(v.error, 1.0 / 20);
  const auto strict = accuracy_verdict({"arrest_position", 0.001, 5e-5}, ladder, 0, 160, runs);
  EXPECT_EQ(strict.state, AccuracyVerdict::State::run_next); // 0.05 m is 0.4 %
}

TEST(AccuracyTarget, StopsAtTheCapWithItsBestEstimate) {
  std::vector<StudyRun> runs = {timed(10), timed(20), timed(40)};
  const auto v = accuracy_verdict(arrival(1e-5), ladder, 0, 40, runs);
  EXPECT_EQ(v.state, AccuracyVerdict::State::mesh_cap);
  EXPECT_DOUBLE_EQ(v.n_d, 40);
  EXPECT_NE(v.reason.find("n_d_max"), std::string::npos) << v.reason;
}

TEST(AccuracyTarget, FailsWhenARunHasNoValue) {
  std::vector<StudyRun> runs = {timed(10), run_with(20, {{"arrival_time_at_probe", nullptr}})};
  const auto v = accuracy_verdict(arrival(1e-3), ladder, 0, 160, runs);
  EXPECT_EQ(v.state, AccuracyVerdict::State::failed);
  EXPECT_NE(v.reason.find("n_d = 20"), std::string::npos) << v.reason;
}

TEST(AccuracyTarget, ReadsDottedMetrics) {
  const auto run = run_with(10, {{"rupture_speed", {{"max", 3000.0}, {"mean", 2500.0}}}});
  EXPECT_DOUBLE_EQ(accuracy_metric(run, "rupture_speed.max"), 3000.0);
  EXPECT_DOUBLE_EQ(accuracy_metric(run, "rupture_speed.mean"), 2500.0);
  EXPECT_TRUE(std::isnan(accuracy_metric(run, "rupture_speed.min")));
  EXPECT_TRUE(std::isnan(accuracy_metric(run, "arrest_position")));
}

TEST(AccuracyTarget, StartSkipsMeshesTheDatabaseShowsTooCoarse) {
  std::string why;
  EXPECT_EQ(accuracy_start(arrival(5e-4), ladder, 160, {}, why), 0u);
  EXPECT_NE(why.find("first mesh"), std::string::npos);
  // Known: 10 and 20 (0.14 %: too coarse for 0.05 %); start at 20, its run reused.
  std::vector<StudyRun> known = {timed(10), timed(20)};
  EXPECT_EQ(accuracy_start(arrival(5e-4), ladder, 160, known, why), 1u);
  EXPECT_NE(why.find("n_d = 20"), std::string::npos) << why;
  // Known 10, 20, 40, 80: (20, 40) gives 6.9e-4 by Richardson, (40, 80) 3.5e-4: start at 40.
  known.push_back(timed(40));
  known.push_back(timed(80));
  EXPECT_EQ(accuracy_start(arrival(5e-4), ladder, 160, known, why), 2u);
  // A loose target met by the first pair: start at the first mesh.
  EXPECT_EQ(accuracy_start(arrival(0.01), ladder, 160, known, why), 0u);
}
