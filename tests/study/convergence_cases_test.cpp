// The shared convergence cases (tests/study/convergence_cases.json) under the server's rules.
// tests/clients/test_unit.py runs the same file through the Python client's rules, so that a
// local plot colours a run as the server's map does.
#include "api/study/convergence.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using nlohmann::json;
using slipfront::api::StudyRun;

json cases() {
  std::ifstream in(SLIPFRONT_CONVERGENCE_CASES);
  if (!in) throw std::runtime_error("cannot open " + std::string(SLIPFRONT_CONVERGENCE_CASES));
  return json::parse(in).at("cases");
}

StudyRun run_of(const json& j) {
  StudyRun run;
  run.id = j.at("id").get<std::string>();
  run.L = j.at("L").get<double>();
  run.n_d = j.at("n_d").get<double>();
  run.status = slipfront::api::parse_status(j.at("status").get<std::string>()).value();
  if (!j.at("metrics").is_null()) run.metrics = j.at("metrics");
  return run;
}

TEST(ConvergenceCases, TheFileHasCasesOfEveryStatus) {
  std::map<std::string, int> seen;
  for (const json& c : cases())
    for (const auto& [id, status] : c.at("expected").items())
      ++seen[status.get<std::string>()];
  for (const char* status :
       {"converged", "not_converged", "unknown", "diverged", "pending", "failed"})
    EXPECT_GT(seen[status], 0) << status;
}

TEST(ConvergenceCases, TheServerRulesGiveTheExpectedStatuses) {
  for (const json& c : cases()) {
    std::vector<StudyRun> runs;
    for (const json& r : c.at("runs"))
      runs.push_back(run_of(r));
    const auto statuses = slipfront::api::convergence_statuses(runs);
    ASSERT_EQ(statuses.size(), c.at("expected").size()) << c.at("name");
    for (const auto& s : statuses)
      EXPECT_EQ(slipfront::api::to_string(s.status), c.at("expected").at(s.run_id))
          << c.at("name") << ": run " << s.run_id << " (" << s.reason << ")";
  }
}

} // namespace
