#include "server/core/job.hpp"
#include "server/core/priority.hpp"
#include "server/http/job_json.hpp"

#include <gtest/gtest.h>

using namespace slipfront::server;

TEST(JobState, ForwardTransitionsOnly) {
  EXPECT_TRUE(transition_allowed(JobStatus::queued, JobStatus::running));
  EXPECT_TRUE(transition_allowed(JobStatus::queued, JobStatus::cancelled));
  EXPECT_FALSE(transition_allowed(JobStatus::queued, JobStatus::succeeded));
  EXPECT_TRUE(transition_allowed(JobStatus::running, JobStatus::succeeded));
  EXPECT_TRUE(transition_allowed(JobStatus::running, JobStatus::failed));
  EXPECT_TRUE(transition_allowed(JobStatus::running, JobStatus::cancelled));
  for (auto final_status : {JobStatus::succeeded, JobStatus::failed, JobStatus::cancelled})
    for (auto to : {JobStatus::queued, JobStatus::running, JobStatus::succeeded, JobStatus::failed,
                    JobStatus::cancelled}) {
      EXPECT_FALSE(transition_allowed(final_status, to));
      EXPECT_FALSE(transition_allowed(final_status, to, TransitionKind::recovery));
    }
}

TEST(JobState, BackToQueuedOnlyForRecovery) {
  EXPECT_FALSE(transition_allowed(JobStatus::running, JobStatus::queued));
  EXPECT_TRUE(transition_allowed(JobStatus::running, JobStatus::queued, TransitionKind::recovery));
}

TEST(JobState, StatusNamesRoundTrip) {
  for (auto s : {JobStatus::queued, JobStatus::running, JobStatus::succeeded, JobStatus::failed,
                 JobStatus::cancelled})
    EXPECT_EQ(parse_status(to_string(s)), s);
  EXPECT_FALSE(parse_status("done").has_value());
}

TEST(JobState, ProjectionKeepsIdAndAskedFields) {
  Job job;
  job.id.assign(32, 'a');
  auto j = job_to_json(job, {"status", "nonexistent"});
  EXPECT_EQ(j.size(), 2u);
  EXPECT_EQ(j["id"].get<std::string>(), job.id);
  EXPECT_EQ(j["status"].get<std::string>(), "queued");
}

// The one range of a priority, for the job and study bodies and the query parameter.
TEST(JobState, PriorityIsAnIntegerInItsRange) {
  for (long p : {-100L, 0L, 100L})
    EXPECT_EQ(priority_of(p), std::optional<int>(static_cast<int>(p)));
  EXPECT_EQ(priority_of(nlohmann::json(-100)), std::optional<int>(-100));
  EXPECT_EQ(priority_of(nlohmann::json(7)), std::optional<int>(7));
  for (long p : {-101L, 101L, 1L << 40})
    EXPECT_FALSE(priority_of(p)) << p;
  for (const nlohmann::json& bad : {nlohmann::json(101), nlohmann::json(-101), nlohmann::json(1.5),
                                    nlohmann::json("5"), nlohmann::json(true), nlohmann::json()})
    EXPECT_FALSE(priority_of(bad)) << bad.dump();
  // Integers past 64 bits are refused, not wrapped (2^64 - 1 once read as -1).
  for (const nlohmann::json& huge :
       {nlohmann::json(18446744073709551615u), nlohmann::json(9223372036854775808u),
        nlohmann::json(-9223372036854775807 - 1)})
    EXPECT_FALSE(priority_of(huge)) << huge.dump();
  EXPECT_EQ(priority_rule(), "must be an integer in [-100, 100]");
}
