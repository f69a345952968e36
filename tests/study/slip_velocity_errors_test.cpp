// speed_accuracy_by_regime and SlipVelocityErrors (api/study/speed_accuracy.hpp): what
// GET /studies/{id}/speed-accuracy lists, without the server and its result files.
#include "api/study/speed_accuracy.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace {

using nlohmann::json;
using namespace slipfront::api;

StudyRun measured(const std::string& id, double L, double n_d, double distance) {
  json metrics = {
      {"outcome", "arrested"}, {"propagation_distance", distance}, {"arrival_time_at_probe", 8.0}};
  return {id, L, n_d, JobStatus::succeeded, metrics, 1.0, 1.0};
}

// Two converged meshes of one L: the finer one (id "b") is the reference of both.
std::vector<StudyRun> converged_pair(const std::string& prefix) {
  return {measured(prefix + "a", 1e-4, 10, 12.0), measured(prefix + "b", 1e-4, 20, 12.0)};
}

TEST(SlipVelocityErrors, GroupsByRegimeReadsEachRecordOnceAndGivesTheL2Error) {
  std::vector<RegimeRun> runs;
  for (const char* regime : {"regularised", "coulomb"})
    for (const StudyRun& run : converged_pair(regime))
      runs.push_back({regime, run});
  std::map<std::string, int> reads;
  SlipVelocityErrors errors([&](const std::string& id, std::string&) {
    ++reads[id];
    const double scale = id.back() == 'a' ? 1.1 : 1.0; // the coarse record is 10 % larger
    return std::optional<ProbeSeries>(ProbeSeries{{0.0, 1.0, 2.0}, {scale, scale, scale}, 6.0});
  });
  const json list = speed_accuracy_by_regime(runs, errors);
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0]["regime"], "coulomb"); // regimes in name order
  EXPECT_EQ(list[2]["regime"], "regularised");
  EXPECT_EQ(list[0]["job_id"], "coulomba");
  EXPECT_NEAR(list[0]["errors"]["slip_velocity_l2"].get<double>(), 0.1, 1e-12);
  EXPECT_EQ(list[1]["errors"]["slip_velocity_l2"], 0.0); // the reference against itself
  for (const auto& [id, count] : reads)
    EXPECT_EQ(count, 1) << id;
  EXPECT_EQ(errors.probe_x1(), 6.0);
}

TEST(SlipVelocityErrors, SaysWhyAnErrorIsMissing) {
  std::vector<RegimeRun> runs;
  for (const StudyRun& run : converged_pair(""))
    runs.push_back({"", run});
  runs.push_back({"", measured("lonely", 2e-4, 10, 12.0)}); // no converged run of its L
  SlipVelocityErrors errors([](const std::string& id, std::string& why) {
    why = "no result file for " + id;
    return std::optional<ProbeSeries>();
  });
  const json list = speed_accuracy_by_regime(runs, errors);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_FALSE(list[0].contains("regime"));
  EXPECT_TRUE(list[0]["errors"]["slip_velocity_l2"].is_null());
  EXPECT_EQ(list[0]["slip_velocity_l2_unavailable"], "no result file for a");
  EXPECT_EQ(list[2]["slip_velocity_l2_unavailable"],
            "no reference run (this L has no mesh-converged run)");
  EXPECT_TRUE(std::isnan(errors.probe_x1()));
}

} // namespace
