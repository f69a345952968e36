// The jobs that workers are running right now: live progress (fresher than the database,
// which is written every few seconds) and the cancel flag handed to the solver.
#pragma once

#include "server/core/job.hpp"

#include <atomic>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

struct RunningJob {
  std::atomic<bool> cancel{false};         // read by the solver every step
  std::atomic<bool> user_cancelled{false}; // cancel came from the API: final state cancelled
  std::string cancelled_by;
  // Set (under `mutex`) once the solver has returned: from then on no cancel is accepted, and
  // one accepted before is honoured by the worker (finish()).
  bool finishing = false;
  std::mutex mutex;
  JobProgress progress;

  // The run has stopped stepping: returns whether a cancel from the API was accepted before
  // (the worker then ends the job cancelled, whatever the run's outcome).
  bool finish() {
    std::lock_guard lock(mutex);
    finishing = true;
    return user_cancelled;
  }

  // The user whose cancel stopped it ("" if none was named).
  std::string canceller() {
    std::lock_guard lock(mutex);
    return cancelled_by;
  }
};

class RunningJobs {
public:
  std::shared_ptr<RunningJob> add(const std::string& id);
  void remove(const std::string& id);
  std::shared_ptr<RunningJob> find(const std::string& id) const;
  std::optional<JobProgress> progress(const std::string& id) const;
  enum class CancelRequest {
    requested,   // the flag is set: the job will end cancelled
    finishing,   // its run has ended and its result is being stored: it will not be cancelled
    not_running, // not running here
  };
  CancelRequest request_cancel(const std::string& id, const std::string& user);
  // Drain: every running job stops at its next step (and is re-queued by its worker).
  void cancel_all_for_drain();
  std::size_t size() const;

private:
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<RunningJob>> jobs_;
};

} // namespace slipfront::server
