// The SLURM executor (docs/cluster.md): a job's whole life on the cluster — submit, poll,
// finish, cancel, adopt after a restart. Over 400 lines on purpose: that state machine reads
// best in one file; its parts (client, job directory, state map) are in their own files.
#include "server/run/slurm/slurm_executor.hpp"

#include "api/job_spec.hpp"
#include "api/run_files.hpp"
#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/core/storage_error.hpp"
#include "server/run/slurm/child_process.hpp"

#include <cmath>
#include <filesystem>

namespace slipfront::server {

namespace fs = std::filesystem;
using steady = std::chrono::steady_clock;

namespace {

// SLURM states after which the job may be tried again elsewhere: the run itself was fine.
bool lost_with_its_node(const std::string& state) {
  return state == "NODE_FAIL" || state == "BOOT_FAIL" || state == "PREEMPTED";
}

int job_threads(const Job& job) {
  if (job.spec.is_object() && job.spec.contains("threads") &&
      job.spec["threads"].is_number_integer())
    return std::max(0, job.spec["threads"].get<int>()); // 0: all of the node's threads
  return 1;
}

// Moves the run's result from the shared dir into the data dir: a rename on the same file
// system, else a copy (checked against the report's SHA-256) renamed into place. Throws.
ResultFile move_result(const std::string& from, const std::string& data_dir,
                       const std::string& relative, const ResultFile& reported) {
  const std::string to = data_dir + "/" + relative;
  const std::string& sha = reported.sha256;
  const std::uint64_t bytes = reported.size;
  std::error_code ec;
  if (!fs::exists(from, ec)) {
    if (fs::exists(to, ec) && api::sha256_file(to) == sha) return {relative, bytes, sha};
    throw std::runtime_error("the run reported a result file, but " + from + " is missing");
  }
  fs::rename(from, to, ec);
  if (ec == std::errc::cross_device_link) {
    const std::string temporary = to + ".tmp";
    fs::copy_file(from, temporary, fs::copy_options::overwrite_existing, ec);
    if (ec) throw std::runtime_error("copying " + from + " to " + temporary + ": " + ec.message());
    if (api::sha256_file(temporary) != sha) {
      fs::remove(temporary, ec);
      throw std::runtime_error("the copy of " + from +
                               " does not have the SHA-256 the run "
                               "reported (the shared file system served another version?)");
    }
    fs::rename(temporary, to, ec);
    if (!ec) fs::remove(from, ec), ec.clear();
  }
  if (ec) throw std::runtime_error("moving " + from + " to " + to + ": " + ec.message());
  return {relative, bytes, sha};
}

} // namespace

SlurmExecutor::SlurmExecutor(SlurmExecutorOptions options, JobStore& store, JobQueue& queue,
                             RunningJobs& running, ServerStats& stats)
    : options_(std::move(options)), store_(store), queue_(queue), running_(running), stats_(stats),
      client_(options_.slurm) {}

SlurmExecutor::~SlurmExecutor() {
  drain();
}

void SlurmExecutor::start() {
  std::error_code ec;
  fs::create_directories(options_.shared_dir + "/jobs", ec);
  if (ec)
    throw std::runtime_error("--shared-dir: cannot create " + options_.shared_dir +
                             "/jobs: " + ec.message());
  // A server that cannot submit should say so at start, not job by job.
  for (const char* tool : {"sbatch", "squeue", "scancel"}) {
    try {
      run_program({tool, "--version"}, options_.slurm.command_timeout_s);
    } catch (const std::exception& e) {
      throw std::runtime_error(std::string("--executor slurm: ") + e.what() +
                               " (install SLURM's client commands and put them in PATH; "
                               "docs/cluster.md)");
    }
  }
  for (const Job& job : store_.running_slurm_jobs()) {
    Tracked t;
    t.id = job.id;
    t.slurm_job_id = job.slurm_job_id;
    t.entry = running_.add(job.id);
    t.attempts = job.attempts;
    t.state_text = job.slurm_state;
    t.started_at = job.started_at;
    tracked_[job.id] = std::move(t);
    log_info("job " + job.id + ": re-attached to SLURM job " + job.slurm_job_id + " (" +
             job.slurm_state + ")");
  }
  thread_ = std::thread([this] { loop(); });
}

void SlurmExecutor::drain() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  queue_.close();
  if (thread_.joinable()) thread_.join();
  // The jobs stay in SLURM and running in the database: the next start re-attaches.
  for (auto& [id, t] : tracked_)
    running_.remove(id);
  if (!tracked_.empty())
    log_info(std::to_string(tracked_.size()) +
             " job(s) left running in SLURM; the next start re-attaches to them");
  tracked_.clear();
}

bool SlurmExecutor::stopping() {
  std::lock_guard lock(mutex_);
  return stopping_;
}

void SlurmExecutor::loop() {
  auto next_poll = steady::now();
  const auto interval = std::chrono::duration_cast<steady::duration>(
      std::chrono::duration<double>(options_.poll_interval_s));
  while (!stopping()) {
    if (steady::now() >= next_poll) {
      try {
        poll();
      } catch (const std::exception& e) {
        log_error(std::string("slurm executor: following the jobs: ") + e.what());
      }
      next_poll = steady::now() + interval;
    }
    submit_from_queue(next_poll);
  }
}

void SlurmExecutor::submit_from_queue(steady::time_point until) {
  while (!stopping() && steady::now() < until) {
    const bool room = static_cast<int>(tracked_.size()) < options_.max_jobs;
    if (!room || steady::now() < paused_until_ || queue_.closed()) {
      std::unique_lock lock(mutex_);
      wake_.wait_until(lock, until, [this] { return stopping_; });
      return;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - steady::now());
    auto id = queue_.pop_for(static_cast<int>(std::max<long long>(1, left.count())));
    if (!id) continue;
    try {
      submit(*id);
    } catch (const std::exception& e) {
      log_error("slurm executor: job " + *id + ": " + e.what());
      if (storage_unavailable(e)) stats_.record_storage_error(e.what());
      auto entry = running_.find(*id);
      if (entry && entry->user_cancelled) { // cancelled through the API meanwhile: honour it
        try {
          Tracked t;
          t.id = *id;
          t.entry = entry;
          fail_or_cancel(t, "");
          continue;
        } catch (const std::exception& again) {
          log_error("job " + *id + ": storing its cancel: " + again.what());
        }
      }
      running_.remove(*id);
      // Not lost: queued or running without a SLURM job in the database; put it back.
      try {
        store_.requeue(*id);
        if (auto job = store_.get(*id); job && job->status == JobStatus::queued)
          queue_.push_unbounded(*id, job->priority);
      } catch (const std::exception& again) {
        log_error("job " + *id + ": re-queueing it (the next start-up will): " + again.what());
      }
      paused_until_ = steady::now() + std::chrono::seconds(5);
    }
  }
}

void SlurmExecutor::submit(const std::string& id) {
  // Registered before the job is marked running, so that a cancel arriving in between
  // either finds it still queued (and wins) or finds the flag (then scancel follows).
  auto entry = running_.add(id);
  if (!store_.mark_running(id, now_iso8601(), "", options_.code_version, "slurm")) {
    running_.remove(id); // cancelled while queued
    return;
  }
  auto job = store_.get(id);
  if (!job) throw std::runtime_error("job vanished from the store after it was marked running");
  const SlurmJobDir dir(options_.shared_dir, id);
  const std::int64_t memory_mb = slurm_memory_mb(job->memory_estimate_bytes);
  SbatchRequest request{"slipfront-" + id, dir.script(),      dir.path(),
                        dir.log(),         job_threads(*job), memory_mb};
  std::string slurm_job_id;
  Tracked unsent{id, "", entry, job->attempts, "", job->started_at, {}, false, 0, job->priority};
  try {
    dir.prepare(*job, options_.binary, static_cast<double>(memory_mb) * 1024.0 * 1024.0);
  } catch (const std::exception& e) {
    fail_or_cancel(unsent, "preparing the job's files in --shared-dir: " + std::string(e.what()));
    return;
  }
  try {
    slurm_job_id = client_.submit(request);
  } catch (const SlurmError& e) {
    if (e.transient()) throw; // put back in the queue; submissions pause a few seconds
    fail_or_cancel(unsent, "SLURM refused the job: " + std::string(e.what()));
    return;
  } catch (const std::exception& e) { // sbatch could not be started at all
    fail_or_cancel(unsent, "submitting to SLURM: " + std::string(e.what()));
    return;
  }
  Tracked t{id, slurm_job_id, entry, job->attempts, "PENDING", job->started_at,
            {}, false,        0,     job->priority};
  try {
    store_.set_slurm_job(id, slurm_job_id, "PENDING");
  } catch (const std::exception& e) { // the SLURM job exists: follow it, store its id later
    log_error("job " + id + ": storing SLURM job " + slurm_job_id + " (tried again): " + e.what());
    if (storage_unavailable(e)) stats_.record_storage_error(e.what());
    t.id_stored = false;
  }
  tracked_[id] = t;
  log_info("job " + id + " (" + job->name + ") submitted to SLURM as job " + slurm_job_id + " (" +
           (request.cpus > 0 ? std::to_string(request.cpus) + " cpu" : std::string("whole node")) +
           ", " + std::to_string(memory_mb) + " MiB)");
}

void SlurmExecutor::poll() {
  if (tracked_.empty()) return;
  std::map<std::string, SlurmJobState> states;
  try {
    states = client_.query();
    squeue_failing_ = false;
  } catch (const std::exception& e) {
    // Never take a job for lost because the controller did not answer.
    if (!squeue_failing_) log_error(std::string("slurm executor: ") + e.what());
    squeue_failing_ = true;
    return;
  }
  std::vector<std::string> unseen;
  for (const auto& [id, t] : tracked_)
    if (!states.count(t.slurm_job_id)) unseen.push_back(t.slurm_job_id);
  for (auto& [slurm_id, state] : client_.query_accounting(unseen))
    states.emplace(slurm_id, state);

  std::vector<std::string> done;
  for (auto& [id, t] : tracked_) {
    try {
      auto it = states.find(t.slurm_job_id);
      bool ended = false;
      if (it == states.end()) {
        ended = lost(t);
      } else {
        t.unseen_polls = 0;
        follow(t, it->second);
        if (slurm_phase(it->second.state) == SlurmPhase::ended) ended = collect(t, it->second);
      }
      if (ended) done.push_back(id);
    } catch (const std::exception& e) { // tried again at the next poll
      log_error("job " + id + " (SLURM job " + t.slurm_job_id + "): " + e.what());
      if (storage_unavailable(e)) stats_.record_storage_error(e.what());
    }
  }
  for (const auto& id : done)
    tracked_.erase(id);
}

void SlurmExecutor::follow(Tracked& t, const SlurmJobState& state) {
  if (!t.id_stored) { // throws while the storage does not answer: tried at the next poll
    store_.set_slurm_job(t.id, t.slurm_job_id, t.state_text);
    t.id_stored = true;
  }
  const SlurmJobDir dir(options_.shared_dir, t.id);
  if (auto progress = dir.read_progress()) {
    {
      std::lock_guard lock(t.entry->mutex);
      t.entry->progress = *progress;
    }
    const auto now = steady::now();
    if (std::chrono::duration<double>(now - t.last_db_progress).count() >=
        options_.db_progress_interval_s) {
      t.last_db_progress = now;
      store_.update_progress(t.id, *progress);
    }
  }
  const std::string text = describe_slurm_state(state);
  if (text != t.state_text) {
    store_.update_slurm_state(t.id, text,
                              slurm_phase(state.state) == SlurmPhase::waiting ? "" : state.node);
    t.state_text = text;
  }
  if (t.entry->user_cancelled && !t.scancel_sent && slurm_phase(state.state) != SlurmPhase::ended) {
    client_.cancel(t.slurm_job_id); // throws: tried again at the next poll
    t.scancel_sent = true;
    log_info("job " + t.id + ": scancel " + t.slurm_job_id);
  }
}

bool SlurmExecutor::collect(Tracked& t, const SlurmJobState& state) {
  const SlurmJobDir dir(options_.shared_dir, t.id);
  const std::string finished_at = now_iso8601();
  std::optional<nlohmann::json> report;
  try {
    report = dir.read_report();
  } catch (const std::exception& e) {
    return fail_or_cancel(t, e.what());
  }
  if (!report) {
    if (t.entry->user_cancelled) return fail_or_cancel(t, "");
    if (lost_with_its_node(state.state)) return requeue_or_fail(t, slurm_failure_reason(state));
    std::string reason = slurm_failure_reason(state);
    if (state.state == "FAILED" || state.state == "COMPLETED" || state.state == "UNKNOWN") {
      if (auto code = dir.read_exit_code())
        reason = "slipfront run exited with " + std::to_string(*code) + " in SLURM job " +
                 t.slurm_job_id + (state.node.empty() ? "" : " on " + state.node);
    }
    const std::string log = dir.log_tail();
    return fail_or_cancel(t, log.empty() ? reason : reason + "; its log ends: " + log);
  }

  RunRecord record = api::run_record_of_report(*report);
  record.finished_at = finished_at;
  record.wall_time_s = seconds_between(t.started_at, finished_at);
  if (!std::isfinite(record.wall_time_s)) record.wall_time_s = 0.0;
  if (record.metrics.is_object() && record.metrics.contains("wall_time_s") &&
      record.metrics["wall_time_s"].is_number())
    record.wall_time_s = record.metrics["wall_time_s"].get<double>();
  if (record.status == JobStatus::succeeded && record.result.path.empty()) {
    record.status = JobStatus::failed;
    record.error = "the run's report names no result file";
  } else if (record.status == JobStatus::succeeded) {
    try {
      record.result =
          move_result(dir.result(), options_.data_dir, result_relative_path(t.id), record.result);
    } catch (const std::exception& e) {
      record.status = JobStatus::failed;
      record.error = std::string("collecting the result: ") + e.what();
      record.result = {};
    }
  }
  if (!store_.finish(t.id, record))
    log_error("job " + t.id + ": was no longer running when its SLURM job ended");
  if (record.status == JobStatus::succeeded) dir.remove(); // failed: kept for its log
  finished(t.id, to_string(record.status), record.wall_time_s, record.error);
  return true;
}

bool SlurmExecutor::lost(Tracked& t) {
  // squeue forgets an ended job after MinJobAge; a few polls tell a gap from a loss.
  if (++t.unseen_polls < 3) return false;
  const SlurmJobDir dir(options_.shared_dir, t.id);
  std::error_code ec;
  if (fs::exists(dir.report(), ec) || fs::exists(dir.exit_code(), ec))
    return collect(t, SlurmJobState{t.slurm_job_id, "UNKNOWN", "", ""});
  if (t.entry->user_cancelled) return fail_or_cancel(t, "");
  return requeue_or_fail(t, "SLURM job " + t.slurm_job_id +
                                " is no longer known to squeue or sacct and left no report "
                                "(lost)");
}

bool SlurmExecutor::requeue_or_fail(Tracked& t, const std::string& reason) {
  if (t.attempts >= options_.max_attempts)
    return fail_or_cancel(t,
                          reason + "; failed after " + std::to_string(t.attempts) + " attempt(s)");
  if (store_.requeue(t.id)) queue_.push_unbounded(t.id, t.priority);
  running_.remove(t.id);
  stats_.record_run("requeued", 0.0);
  log_error("job " + t.id + " queued again (attempt " + std::to_string(t.attempts) + " of " +
            std::to_string(options_.max_attempts) + "): " + reason);
  return true;
}

bool SlurmExecutor::fail_or_cancel(Tracked& t, const std::string& reason) {
  RunRecord record =
      t.entry->user_cancelled ? cancelled_run(t.entry->canceller()) : failed_run(reason);
  if (record.status == JobStatus::cancelled) SlurmJobDir(options_.shared_dir, t.id).remove();
  record.finished_at = now_iso8601();
  record.wall_time_s = seconds_between(t.started_at, record.finished_at);
  if (!std::isfinite(record.wall_time_s)) record.wall_time_s = 0.0;
  if (!store_.finish(t.id, record))
    log_error("job " + t.id + ": was no longer running when its SLURM job ended");
  finished(t.id, to_string(record.status), record.wall_time_s, record.error);
  return true;
}

void SlurmExecutor::finished(const std::string& id, const std::string& outcome, double wall_time_s,
                             const std::string& error) {
  running_.remove(id);
  if (options_.on_finished) {
    try {
      options_.on_finished(id);
    } catch (const std::exception& e) {
      log_error("job " + id + ": completion callback: " + e.what());
    }
  }
  stats_.record_run(outcome, wall_time_s);
  log_info("job " + id + " " + outcome + " in SLURM after " + std::to_string(wall_time_s) + " s" +
           (error.empty() ? "" : ": " + error));
}

} // namespace slipfront::server
