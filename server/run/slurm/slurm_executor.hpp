// The SLURM executor: each queued job becomes one sbatch job running `slipfront run` on a
// compute node (docs/cluster.md). One thread does everything, in a loop:
//   submit   while fewer than `max_jobs` are in SLURM: pop a job, mark it running, write its
//            spec and batch script to <shared-dir>/jobs/<id>/, sbatch it (--cpus-per-task =
//            its threads, --mem from its memory estimate), store the SLURM job id;
//   follow   every `poll_interval_s`: one squeue for all jobs, their progress files,
//            scancel for jobs cancelled through the API;
//   collect  a job SLURM reports ended: its report and result file are moved into the data
//            dir and stored in one transaction; without a report, the SLURM state (TIMEOUT,
//            OUT_OF_MEMORY, NODE_FAIL, ...) is the reason it failed.
// Only this server process writes the database; compute nodes write files only.
//
// At start it re-attaches to the jobs the database has running in SLURM (a restart does
// not run them again). A job SLURM no longer knows and that left no files is lost: it is
// re-queued (at most `max_attempts` starts in all), then failed with the reason.
#pragma once

#include "server/core/server_stats.hpp"
#include "server/db/job_store.hpp"
#include "server/run/executor.hpp"
#include "server/run/job_queue.hpp"
#include "server/run/running_jobs.hpp"
#include "server/run/slurm/slurm_client.hpp"
#include "server/run/slurm/slurm_job_dir.hpp"

#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

namespace slipfront::server {

struct SlurmExecutorOptions {
  SlurmSettings slurm;
  std::string shared_dir;   // seen at the same path by the server and the compute nodes
  std::string data_dir;     // results are collected to data_dir/results/<id>.h5
  std::string binary;       // slipfront on the compute nodes
  std::string code_version; // this build's (stored when a job starts)
  int max_jobs = 100;       // jobs kept in SLURM at once; the rest wait in the queue
  double poll_interval_s = 2.0;
  double db_progress_interval_s = 3.0;
  int max_attempts = 3; // starts of a job SLURM lost (node failure) before it is failed
  std::function<void(const std::string& id)> on_finished; // after a final status
};

class SlurmExecutor : public Executor {
public:
  SlurmExecutor(SlurmExecutorOptions options, JobStore& store, JobQueue& queue,
                RunningJobs& running, ServerStats& stats);
  ~SlurmExecutor() override;
  SlurmExecutor(const SlurmExecutor&) = delete;
  SlurmExecutor& operator=(const SlurmExecutor&) = delete;

  const char* name() const override { return "slurm"; }
  // Re-attaches to the jobs running in SLURM, then starts the thread.
  void start() override;
  void drain() override;
  int slots() const override { return options_.max_jobs; }

private:
  struct Tracked {
    std::string id;
    std::string slurm_job_id;
    std::shared_ptr<RunningJob> entry;
    int attempts = 0;
    std::string state_text; // last stored slurm_state
    std::string started_at;
    std::chrono::steady_clock::time_point last_db_progress{};
    bool scancel_sent = false;
    int unseen_polls = 0;  // consecutive polls in which SLURM did not know the job
    int priority = 0;      // its queue priority, if it must be queued again
    bool id_stored = true; // slurm_job_id is in the database (else stored at the next poll)
  };

  void loop();
  bool stopping();
  // Pops and submits jobs while there is room; returns once the queue is empty (after
  // waiting at most until `until`) or full.
  void submit_from_queue(std::chrono::steady_clock::time_point until);
  void submit(const std::string& id);
  void poll();
  void follow(Tracked& job, const SlurmJobState& state);
  // The job ended in SLURM (or was lost): stores its final record. False if it must be
  // tried again at the next poll (the storage did not answer).
  bool collect(Tracked& job, const SlurmJobState& state);
  bool lost(Tracked& job);
  // Back to the queue (SLURM lost it with its node), or failed after max_attempts starts.
  bool requeue_or_fail(Tracked& job, const std::string& reason);
  // Final record without a result: cancelled if the API asked, else failed with `reason`.
  bool fail_or_cancel(Tracked& job, const std::string& reason);
  void finished(const std::string& id, const std::string& outcome, double wall_time_s,
                const std::string& error);

  SlurmExecutorOptions options_;
  JobStore& store_;
  JobQueue& queue_;
  RunningJobs& running_;
  ServerStats& stats_;
  SlurmClient client_;
  std::map<std::string, Tracked> tracked_;               // by job id; the thread's own
  std::chrono::steady_clock::time_point paused_until_{}; // after sbatch could not reach SLURM
  bool squeue_failing_ = false;                          // logged once per failing streak
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

} // namespace slipfront::server
