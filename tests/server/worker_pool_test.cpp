// The worker pool with runners injected through the JobRunner interface: failure, cancel
// and drain paths that the real solver cannot be made to take on demand.
#include "server/core/job_id.hpp"
#include "server/run/worker_pool.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

using namespace slipfront::server;
namespace fs = std::filesystem;
using slipfront::server::testing::TempDir;

namespace {

// Behaves as the job's name says: "throw", "wait" (until cancelled, at most 10 s),
// "last-step" (its steps done, writes its file for 300 ms whatever the cancel flag says, then
// succeeds), else succeed.
class ScriptedRunner : public JobRunner {
public:
  RunRecord run(const Job& job, const std::string& output_path,
                const slipfront::RunHooks& hooks) override {
    RunRecord report;
    if (job.name == "throw") throw std::runtime_error("disk full while writing " + output_path);
    if (job.name == "wait") {
      for (int i = 0; i < 1000 && !hooks.cancel->load(); ++i) {
        slipfront::Progress p;
        p.fraction = 0.01 * i;
        p.step = i;
        hooks.on_progress(p);
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
      }
      if (hooks.cancel->load()) report.status = JobStatus::cancelled;
      return report;
    }
    if (job.name == "last-step") {
      slipfront::Progress p;
      p.fraction = 1.0;
      hooks.on_progress(p);
      std::ofstream(output_path) << "result";
      std::this_thread::sleep_for(std::chrono::milliseconds(300));
    }
    report.metrics = {{"outcome", "arrested"}, {"steps", 10}, {"simulated_time", 2.0}};
    report.front = {{"x1", {0.0}}, {"arrival_time", {0.1}}, {"rupture_speed", {nullptr}}};
    report.result = {output_path, 42, "feed"};
    return report;
  }
};

struct Fixture {
  TempDir dir{"slipfront-pool-"};
  bool results_dir = fs::create_directories(dir.path() / "results"); // before the store
  JobStore store{dir.str() + "/db.sqlite"};
  JobQueue queue{100};
  ScriptedRunner runner;
  RunningJobs running;
  ServerStats stats;
  WorkerPool pool{WorkerOptions{2, dir.str(), "test-version", "test-host", 0.0, 0.01, {}},
                  store,
                  queue,
                  runner,
                  running,
                  stats};

  std::string submit(const std::string& name) {
    Job job;
    job.id = new_job_id();
    job.name = name;
    job.spec = nlohmann::json::object();
    job.spec_sha256 = job.id; // any text: no reuse in these tests
    job.created_at = job.id;
    store.insert(job);
    queue.push(job.id, 0);
    return job.id;
  }

  Job wait_for(const std::string& id, bool (*done)(JobStatus), int seconds = 5) {
    for (int i = 0; i < seconds * 100; ++i) {
      auto job = store.get(id);
      if (job && done(job->status)) return *job;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return *store.get(id);
  }
};

bool final_status(JobStatus s) {
  return is_final(s);
}
bool running_status(JobStatus s) {
  return s == JobStatus::running;
}

} // namespace

TEST(WorkerPool, SuccessFailureAndUserCancel) {
  Fixture f;
  f.pool.start();
  auto ok = f.submit("ok");
  auto bad = f.submit("throw");
  auto slow = f.submit("wait");

  Job done = f.wait_for(ok, final_status);
  EXPECT_EQ(done.status, JobStatus::succeeded);
  EXPECT_EQ(done.result.path, "results/" + ok + ".h5"); // data-dir relative
  EXPECT_EQ(done.code_version, "test-version");
  EXPECT_EQ(done.progress.steps, 10);
  EXPECT_TRUE(f.store.front(ok).has_value());

  Job failed = f.wait_for(bad, final_status);
  EXPECT_EQ(failed.status, JobStatus::failed);
  EXPECT_NE(failed.error.find("disk full while writing"), std::string::npos) << failed.error;
  EXPECT_TRUE(failed.result.path.empty());

  f.wait_for(slow, running_status);
  for (int i = 0; i < 200 && !f.running.progress(slow); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_TRUE(f.running.progress(slow).has_value()) << "live progress is kept in memory";
  EXPECT_EQ(f.running.request_cancel(slow, "alice"), RunningJobs::CancelRequest::requested);
  Job cancelled = f.wait_for(slow, final_status);
  EXPECT_EQ(cancelled.status, JobStatus::cancelled);
  EXPECT_NE(cancelled.error.find("alice"), std::string::npos);
  f.pool.drain();
}

// A cancel accepted after the run's last step is kept (the job ends
// cancelled, its file removed); once the worker has the run's end, a cancel is refused.
TEST(WorkerPool, ACancelAcceptedAfterTheLastStepIsKept) {
  Fixture f;
  f.pool.start();
  auto id = f.submit("last-step");
  for (int i = 0; i < 500 && !f.running.progress(id); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  ASSERT_TRUE(f.running.progress(id).has_value());
  EXPECT_EQ(f.running.request_cancel(id, "alice"), RunningJobs::CancelRequest::requested);
  Job job = f.wait_for(id, final_status);
  EXPECT_EQ(job.status, JobStatus::cancelled);
  EXPECT_TRUE(job.result.path.empty());
  EXPECT_FALSE(fs::exists(f.dir.path() / "results" / (id + ".h5")));
  f.pool.drain();
}

TEST(RunningJobs, ACancelAfterTheRunEndedIsRefusedAsFinishing) {
  RunningJobs running;
  auto entry = running.add("a");
  EXPECT_FALSE(entry->finish()); // no cancel before
  EXPECT_EQ(running.request_cancel("a", "alice"), RunningJobs::CancelRequest::finishing);
  EXPECT_FALSE(entry->user_cancelled);
  EXPECT_FALSE(entry->cancel);
  EXPECT_EQ(running.request_cancel("b", "alice"), RunningJobs::CancelRequest::not_running);
}

TEST(WorkerPool, DrainRequeuesRunningJobs) {
  Fixture f;
  f.pool.start();
  auto slow = f.submit("wait");
  f.wait_for(slow, running_status);
  auto t0 = std::chrono::steady_clock::now();
  f.pool.drain();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
  auto job = f.store.get(slow);
  EXPECT_EQ(job->status, JobStatus::queued) << "drained jobs go back to queued";
  EXPECT_EQ(job->attempts, 1);
  EXPECT_EQ(f.running.size(), 0u);
}

namespace {
// Another connection holding the database's write lock: every write of the store fails
// with SQLITE_BUSY (after its 5 s busy timeout), as writes fail on a full disk.
struct WriteLock {
  explicit WriteLock(const std::string& path) : db(path) {
    db.exec("PRAGMA busy_timeout = 5000"); // the worker may be writing progress right now
    db.exec("BEGIN IMMEDIATE");
  }
  void release() {
    if (held) db.exec("COMMIT");
    held = false;
  }
  ~WriteLock() { release(); }
  Database db;
  bool held = true;
};

} // namespace

// A queued job whose start hit a storage error left the in-memory queue
// and never ran until a restart.
TEST(WorkerPool, JobWhoseStartHitAStorageErrorStaysRunnable) {
  Fixture f;
  auto ok = f.submit("ok");
  WriteLock lock(f.dir.str() + "/db.sqlite");
  f.pool.start();                                       // mark_running fails after 5 s
  std::this_thread::sleep_for(std::chrono::seconds(6)); // the first start has failed
  EXPECT_EQ(f.store.get(ok)->status, JobStatus::queued);
  EXPECT_TRUE(f.stats.last_storage_error().has_value());
  lock.release();
  Job done = f.wait_for(ok, final_status, 20);
  EXPECT_EQ(done.status, JobStatus::succeeded);
  f.pool.drain();
}

// ... and a running job whose end could not be stored stayed `running` forever.
TEST(WorkerPool, EndThatCannotBeStoredIsRetried) {
  Fixture f;
  f.pool.start();
  auto slow = f.submit("wait");
  f.wait_for(slow, running_status);
  WriteLock lock(f.dir.str() + "/db.sqlite");
  EXPECT_EQ(f.running.request_cancel(slow, "alice"),
            RunningJobs::CancelRequest::requested); // finish() now fails
  std::this_thread::sleep_for(std::chrono::seconds(7));
  EXPECT_EQ(f.store.get(slow)->status, JobStatus::running);
  lock.release();
  Job done = f.wait_for(slow, final_status, 20);
  EXPECT_EQ(done.status, JobStatus::cancelled);
  f.pool.drain();
}
