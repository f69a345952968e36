// The study supervisor at start-up: a run of a cancelled study that the recovery queued
// again (it was still stopping when the server went down) is cancelled before any worker
// starts, and the study's final progress is stored.
#include "server/core/job_id.hpp"
#include "server/db/study_store.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_supervisor.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <thread>

using namespace slipfront::server;
namespace api = slipfront::api;
using slipfront::server::testing::TempDir;

namespace {

StudyRecord study_record(api::StudyStatus status) {
  StudyRecord st;
  st.id = new_job_id();
  st.kind = "convergence";
  st.base = nlohmann::json::object();
  st.request = {{"convergence", {{"L", {1e-5}}, {"n_d", {10, 20, 40}}}}};
  st.scene_hash = "scene";
  st.submitted_by = "alice";
  st.created_at = "2024";
  st.status = status;
  return st;
}

Job queued_run(const StudyRecord& st, double n_d) {
  Job job;
  job.id = new_job_id();
  job.name = "run";
  job.spec = nlohmann::json::object();
  job.spec_sha256 = job.id;
  job.created_at = "2024";
  job.study_id = st.id;
  job.submitted_by = st.submitted_by;
  job.n_d = n_d;
  return job;
}

} // namespace

TEST(StudySupervisor, StartCancelsTheRequeuedRunsOfACancelledStudy) {
  TempDir dir("slipfront-supervisor-");
  JobStore store(dir.file("db.sqlite"));
  JobQueue queue(10);
  RunningJobs running;
  JobService service(ServiceOptions{}, store, queue, running);
  StudyStore studies(store);

  StudyRecord cancelled = study_record(api::StudyStatus::cancelled);
  cancelled.runs_total = 2;
  studies.insert(cancelled);
  std::vector<Job> runs = {queued_run(cancelled, 10), queued_run(cancelled, 20)};
  for (const Job& job : runs) {
    store.insert(job);
    queue.push(job.id, 0);
    studies.add_run(cancelled.id, job.id, "", 1e-5, job.n_d);
  }
  ASSERT_EQ(studies.unsettled_cancelled_ids(), std::vector<std::string>{cancelled.id});

  StudySupervisor supervisor(studies, service);
  service.set_on_cancelled([&](const std::string& id) { supervisor.job_finished(id); });
  supervisor.start();
  // Before start() returns, i.e. before the worker pool would start.
  for (const Job& job : runs) {
    EXPECT_EQ(store.get(job.id)->status, JobStatus::cancelled);
    EXPECT_FALSE(queue.contains(job.id));
  }
  std::optional<StudyRecord> after;
  for (int i = 0; i < 500; ++i) { // the step that stores the progress runs on its thread
    after = studies.get(cancelled.id);
    if (after->runs_done == 2) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  supervisor.stop();
  EXPECT_EQ(after->status, api::StudyStatus::cancelled);
  EXPECT_EQ(after->runs_done, 2);
  EXPECT_FALSE(after->finished_at.empty());
  EXPECT_EQ(studies.runs(cancelled.id).size(), 2u); // no further mesh (n_d = 40) submitted
  EXPECT_TRUE(studies.unsettled_cancelled_ids().empty());
}
