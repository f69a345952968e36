// N worker threads that pop jobs from the queue and run them, one at a time each.
//
// Progress goes to RunningJobs at every solver callback (about twice a second) and to the
// database at most every `db_progress_interval_s`. A cancel from the API ends the job as
// cancelled; a drain (SIGTERM) stops the run at its next step and puts the job back to
// queued, to be run again from the start by the next server process.
#pragma once

#include "server/core/server_stats.hpp"
#include "server/db/job_store.hpp"
#include "server/run/executor.hpp"
#include "server/run/job_queue.hpp"
#include "server/run/job_runner.hpp"
#include "server/run/running_jobs.hpp"

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace slipfront::server {

struct WorkerOptions {
  int workers = 1;
  std::string data_dir; // results go to data_dir/results/<id>.h5
  std::string code_version;
  std::string host;
  double db_progress_interval_s = 3.0;
  double progress_interval_s = 0.5; // solver callback period
  // Called (on the worker thread) after a job reached a final status; not for re-queues.
  std::function<void(const std::string& id)> on_finished;
};

class WorkerPool : public Executor {
public:
  WorkerPool(WorkerOptions options, JobStore& store, JobQueue& queue, JobRunner& runner,
             RunningJobs& running, ServerStats& stats);
  ~WorkerPool() override;
  WorkerPool(const WorkerPool&) = delete;
  WorkerPool& operator=(const WorkerPool&) = delete;

  const char* name() const override { return "local"; }
  void start() override;
  // Stop taking jobs, stop the running ones at a safe point, re-queue them, join.
  void drain() override;
  int slots() const override { return options_.workers; }
  int workers() const { return options_.workers; }

private:
  void work();
  void run_one(const std::string& id);
  // After run_one() threw: the job must not be lost between the queue and the database.
  // A job the database still has queued (or running, put back to queued) goes back into
  // the queue; storage errors are retried until the storage answers or the pool drains.
  void keep_runnable(const std::string& id);
  // Waits before retry `attempt` (0.5 s doubling, at most 5 s); false once draining.
  bool back_off(int attempt);
  // Stores the final record, retrying while the storage cannot take writes (disk full);
  // false if the pool drained first (the job stays running in the database: the next
  // start-up re-queues it).
  bool store_final(const std::string& id, const RunRecord& record, bool& was_running);

  WorkerOptions options_;
  JobStore& store_;
  JobQueue& queue_;
  JobRunner& runner_;
  RunningJobs& running_;
  ServerStats& stats_;
  std::atomic<bool> draining_{false};
  std::mutex backoff_mutex_;
  std::condition_variable backoff_cv_;
  std::vector<std::thread> threads_;
};

} // namespace slipfront::server
