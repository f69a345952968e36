// Where queued jobs run. Both executors take jobs from the same JobQueue, drive the same
// job states in the JobStore, publish live progress and honour cancels through RunningJobs,
// and call the same completion callback (studies step on it):
//   local  WorkerPool: N threads of this process (server/run/worker_pool.hpp)
//   slurm  SlurmExecutor: one sbatch job per run on a cluster (server/run/slurm/slurm_executor.hpp)
#pragma once

#include <string>

namespace slipfront::server {

class Executor {
public:
  virtual ~Executor() = default;
  virtual const char* name() const = 0; // "local" or "slurm"
  // Starts taking jobs from the queue.
  virtual void start() = 0;
  // Stops taking jobs and returns once no job is being started or collected. The local
  // executor stops its runs and re-queues them; the SLURM executor leaves its jobs in SLURM,
  // running in the database, for the next start to re-attach to.
  virtual void drain() = 0;
  // Jobs running at once (local: worker threads; slurm: jobs kept in SLURM).
  virtual int slots() const = 0;
};

} // namespace slipfront::server
