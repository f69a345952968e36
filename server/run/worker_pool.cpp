#include "server/run/worker_pool.hpp"

#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/core/storage_error.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <filesystem>

namespace slipfront::server {

WorkerPool::WorkerPool(WorkerOptions options, JobStore& store, JobQueue& queue, JobRunner& runner,
                       RunningJobs& running, ServerStats& stats)
    : options_(std::move(options)), store_(store), queue_(queue), runner_(runner),
      running_(running), stats_(stats) {}

WorkerPool::~WorkerPool() {
  drain();
}

void WorkerPool::start() {
  for (int i = 0; i < options_.workers; ++i)
    threads_.emplace_back([this] { work(); });
}

void WorkerPool::drain() {
  {
    std::lock_guard lock(backoff_mutex_);
    draining_ = true;
  }
  backoff_cv_.notify_all();
  queue_.close();
  running_.cancel_all_for_drain();
  for (auto& t : threads_)
    if (t.joinable()) t.join();
  threads_.clear();
}

void WorkerPool::work() {
  int failures = 0; // consecutive runs that threw: back off, not spin, on a full disk
  while (auto id = queue_.pop()) {
    try {
      run_one(*id);
      failures = 0;
    } catch (const std::exception& e) {
      log_error("worker: job " + *id + ": " + e.what());
      if (storage_unavailable(e)) stats_.record_storage_error(e.what());
      running_.remove(*id);
      keep_runnable(*id);
      back_off(failures++);
    }
  }
}

bool WorkerPool::back_off(int attempt) {
  const double seconds = std::min(5.0, 0.5 * std::pow(2.0, std::min(attempt, 10)));
  std::unique_lock lock(backoff_mutex_);
  backoff_cv_.wait_for(lock, std::chrono::duration<double>(seconds),
                       [this] { return draining_.load(); });
  return !draining_;
}

void WorkerPool::keep_runnable(const std::string& id) {
  for (int attempt = 0;; ++attempt) {
    try {
      auto job = store_.get(id);
      if (!job) return;
      if (job->status == JobStatus::running && store_.requeue(id)) job = store_.get(id);
      if (job && job->status == JobStatus::queued) queue_.push_unbounded(id, job->priority);
      return;
    } catch (const std::exception& e) {
      if (attempt == 0) log_error("job " + id + ": putting it back in the queue: " + e.what());
      if (storage_unavailable(e)) stats_.record_storage_error(e.what());
      // Draining: the database has it queued or running; the next start-up queues it.
      if (!back_off(attempt)) return;
    }
  }
}

bool WorkerPool::store_final(const std::string& id, const RunRecord& record, bool& was_running) {
  for (int attempt = 0;; ++attempt) {
    try {
      was_running = store_.finish(id, record);
      return true;
    } catch (const std::exception& e) {
      if (!storage_unavailable(e)) throw;
      if (attempt == 0)
        log_error("job " + id +
                  ": storing its end (retrying until the storage answers): " + e.what());
      stats_.record_storage_error(e.what());
      if (!back_off(attempt)) return false;
    }
  }
}

void WorkerPool::run_one(const std::string& id) {
  // Registered before the job is marked running, so that a cancel arriving in between
  // either finds it still queued (and wins) or finds the flag.
  auto entry = running_.add(id);
  if (!store_.mark_running(id, now_iso8601(), options_.host, options_.code_version)) {
    running_.remove(id); // cancelled while queued
    return;
  }
  auto job = store_.get(id);
  if (!job) throw std::runtime_error("job vanished from the store after it was marked running");
  if (draining_) {
    store_.requeue(id);
    running_.remove(id);
    return;
  }
  log_info("job " + id + " started (" + job->name + ")");

  using clock = std::chrono::steady_clock;
  const auto started = clock::now();
  auto last_db_write = started;
  RunHooks hooks;
  hooks.cancel = &entry->cancel;
  hooks.progress_interval_s = options_.progress_interval_s;
  hooks.on_progress = [&](const Progress& p) {
    JobProgress jp{p.fraction, p.time, p.duration, p.step, p.eta_s, now_iso8601()};
    {
      std::lock_guard lock(entry->mutex);
      entry->progress = jp;
    }
    auto now = clock::now();
    if (std::chrono::duration<double>(now - last_db_write).count() >=
        options_.db_progress_interval_s) {
      last_db_write = now;
      try {
        store_.update_progress(id, jp);
      } catch (const std::exception& e) { // progress in memory stays fresh; the run goes on
        log_error("job " + id + ": writing progress: " + e.what());
        if (storage_unavailable(e)) stats_.record_storage_error(e.what());
      }
    }
  };

  const std::string relative = result_relative_path(id);
  const std::string output = options_.data_dir + "/" + relative;
  RunRecord record;
  try {
    record = runner_.run(*job, output, hooks);
  } catch (const std::exception& e) {
    record = failed_run(std::string("run failed: ") + e.what());
  }
  const double wall_time_s = std::chrono::duration<double>(clock::now() - started).count();
  bool stopped = record.status == JobStatus::cancelled;
  // A cancel accepted (202) after the last step is kept: the job ends cancelled, its file
  // removed; from here on a cancel is answered 409 "finishing".
  const bool user_cancelled = entry->finish();
  if (user_cancelled && !stopped) {
    std::error_code ec;
    std::filesystem::remove(output, ec);
    stopped = true;
  }
  if (stopped && user_cancelled) record = cancelled_run(entry->canceller());
  // Only a succeeded run leaves a result; the store keeps its data-dir relative path.
  if (record.status != JobStatus::succeeded)
    record.result = {};
  else if (!record.result.path.empty())
    record.result.path = relative;
  record.wall_time_s = wall_time_s;
  record.finished_at = now_iso8601();

  std::string outcome;
  if (stopped && !user_cancelled) {
    store_.requeue(id); // drain: back to queued, run again by the next process
    outcome = "requeued";
  } else {
    bool was_running = false;
    if (!store_final(id, record, was_running)) {
      running_.remove(id);
      log_error("job " + id +
                ": its end could not be stored before the drain; it stays running "
                "in the database and the next start-up queues it again");
      return;
    }
    if (!was_running) log_error("job " + id + ": was no longer running when it finished");
    outcome = to_string(record.status);
  }
  running_.remove(id);
  if (outcome != "requeued" && options_.on_finished) {
    try {
      options_.on_finished(id);
    } catch (const std::exception& e) {
      log_error("job " + id + ": completion callback: " + e.what());
    }
  }
  stats_.record_run(outcome, record.wall_time_s);
  log_info("job " + id + " " + outcome + " after " + std::to_string(record.wall_time_s) + " s" +
           (record.error.empty() ? "" : ": " + record.error));
}

} // namespace slipfront::server
