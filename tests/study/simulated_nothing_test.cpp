// A run that simulated nothing is never a result of a study. A job whose
// time step was 1e-302 s once ended "succeeded" with 0 steps and outcome no_rupture, and a
// convergence study of such runs reported them converged and L_c = 1e-4 (docs/studies.md).
#include "api/study_analysis.hpp"

#include <gtest/gtest.h>

using nlohmann::json;
using namespace slipfront::api;

namespace {

// What the server stored for such a run: succeeded, outcome no_rupture, 0 steps.
StudyRun simulated_nothing(const std::string& id, double L, double n_d) {
  json metrics = {{"outcome", "no_rupture"},
                  {"steps", 0},
                  {"simulated_time", 0.0},
                  {"propagation_distance", 0.0},
                  {"arrival_time_at_probe", nullptr},
                  {"spectral_critical_length", nullptr}};
  return {id, L, n_d, JobStatus::succeeded, metrics, 0.01, 1e6};
}

// A run that did simulate: the same metrics with steps and simulated time.
StudyRun simulated(const std::string& id, double L, double n_d) {
  StudyRun run = simulated_nothing(id, L, n_d);
  (*run.metrics)["steps"] = 4000;
  (*run.metrics)["simulated_time"] = 16.0;
  return run;
}

std::vector<StudyRun> ladder_of(StudyRun (*make)(const std::string&, double, double)) {
  std::vector<StudyRun> runs;
  for (double L : {5e-5, 1e-4})
    for (double n_d : {10.0, 20.0, 40.0})
      runs.push_back(make(std::to_string(L) + "-" + std::to_string(n_d), L, n_d));
  return runs;
}

} // namespace

TEST(SimulatedNothing, RunsOfZeroStepsAreFailedAndGiveNoCriticalLength) {
  const auto runs = ladder_of(simulated_nothing);
  for (const RunConvergence& s : convergence_statuses(runs))
    EXPECT_EQ(to_string(s.status), "failed") << s.run_id << ": " << s.reason;
  const json map = convergence_map(runs);
  for (const auto& [L, n_d] : map["converged_n_d"].items())
    EXPECT_TRUE(n_d.is_null()) << "L = " << L;
  const json lc = critical_length(runs);
  EXPECT_TRUE(lc["L_c"].is_null()) << lc.dump(2);
  EXPECT_EQ(lc["references"], json::array());
  EXPECT_EQ(lc["excluded"].size(), 2u);
}

TEST(SimulatedNothing, TheSameRunsWithStepsDoGiveACriticalLength) {
  // The control: the rule, not the synthetic metrics, is what removes L_c above.
  const json lc = critical_length(ladder_of(simulated));
  EXPECT_EQ(lc["L_c"], 1e-4) << lc.dump(2);
}

TEST(SimulatedNothing, NoSimulatedTimeOrADivergenceAtStepZeroIsNoResultEither) {
  std::vector<StudyRun> runs = ladder_of(simulated);
  (*runs[1].metrics)["simulated_time"] = 0.0; // 5e-5 at n_d 20: steps but no time
  runs[2].status = JobStatus::failed;         // 5e-5 at n_d 40: diverged at step 0
  *runs[2].metrics = {{"outcome", "diverged"}, {"steps", 0}, {"simulated_time", 0.0}};
  const auto statuses = convergence_statuses(runs);
  EXPECT_EQ(to_string(statuses[1].status), "failed");
  EXPECT_EQ(to_string(statuses[2].status), "failed") << "not diverged: nothing ran";
  EXPECT_EQ(to_string(statuses[0].status), "unknown") << "no finer mesh holds a result";
  EXPECT_TRUE(critical_length(runs)["L_c"].is_null());
}
