#include "server/services/job_service.hpp"

#include "server/core/clock.hpp"
#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/core/priority.hpp"

#include "api/job_spec.hpp"
#include "api/json_parse.hpp"
#include "api/number_text.hpp"
#include "api/scene_checks.hpp"

#include <filesystem>

namespace slipfront::server {

JobService::JobService(ServiceOptions options, JobStore& store, JobQueue& queue,
                       RunningJobs& running)
    : options_(std::move(options)), store_(store), queue_(queue), running_(running),
      result_files_(options_.data_dir) {}

ServiceLoad JobService::load() const {
  return {running_.size(), queue_.size(), queue_.limit()};
}

namespace {

using Kind = SubmitResult::Kind;

SubmitResult failure(Kind kind, std::vector<api::FieldError> errors) {
  SubmitResult r;
  r.kind = kind;
  r.errors = std::move(errors);
  return r;
}

// Server-side fields of the body (not part of the job spec): removed before validation.
std::vector<api::FieldError> take_server_fields(nlohmann::json& doc, SubmitOptions& options) {
  std::vector<api::FieldError> errors;
  if (auto it = doc.find("fresh"); it != doc.end()) {
    if (it->is_boolean()) {
      if (!options.fresh) options.fresh = it->get<bool>();
    } else {
      errors.push_back({"/fresh", "must be a boolean"});
    }
    doc.erase(it);
  }
  if (auto it = doc.find("priority"); it != doc.end()) {
    if (const auto priority = priority_of(*it)) {
      if (!options.priority) options.priority = priority;
    } else {
      errors.push_back({"/priority", priority_rule()});
    }
    doc.erase(it);
  }
  return errors;
}

} // namespace

api::ParseResult JobService::validate(nlohmann::json doc) const {
  // One solver thread per job unless the spec asks: N workers use N cores.
  if (doc.is_object() && !doc.contains("threads")) doc["threads"] = 1;
  api::ValidationLimits limits;
  limits.max_memory_bytes = options_.max_memory_bytes;
  limits.max_result_bytes = options_.max_result_bytes;
  api::ParseResult parsed = api::parse_job(doc, limits);
  if (!parsed.ok()) return parsed;
  // A run longer than the server allows is refused with its estimate (docs/server.md).
  const api::CostEstimate estimate = api::estimate_cost(
      parsed.spec->params, parsed.spec->memory_estimate_bytes, options_.cost_model);
  if (estimate.wall_time_s > options_.max_run_seconds) {
    parsed.errors.push_back(
        {"/geometry/nodes_per_meter",
         "the run would take about " + api::wall_time_text(estimate.wall_time_s) +
             " on this server (estimate: " + api::number_text(estimate.steps, 3) +
             " steps of dt = " + api::number_text(estimate.dt, 3) + " s, " +
             std::to_string(estimate.threads) + " thread" + (estimate.threads == 1 ? "" : "s") +
             "), above its limit --max-run-seconds " + api::number_text(options_.max_run_seconds) +
             " s: use fewer nodes per meter, a smaller domain or a shorter duration"});
    parsed.spec.reset();
  }
  return parsed;
}

nlohmann::json JobService::validation_json(const api::JobSpec& spec) const {
  return {{"warnings", api::warnings_json(spec.warnings)},
          {"provenance", api::provenance_json(spec.provenance)},
          {"resolution", api::resolution_json(spec.params)},
          {"estimate", api::estimate_json(api::estimate_cost(
                           spec.params, spec.memory_estimate_bytes, options_.cost_model))}};
}

CheckResult JobService::check(const std::string& body) const {
  CheckResult r;
  auto parsed = api::parse_bounded_json(body);
  if (!parsed.ok()) {
    r.kind = parsed.status == api::JsonParse::Status::syntax ? CheckResult::Kind::bad_json
                                                             : CheckResult::Kind::invalid;
    r.errors = {parsed.error};
    return r;
  }
  if (!parsed.value.is_object()) {
    r.kind = CheckResult::Kind::invalid;
    r.errors = {{"", "the job must be a JSON object"}};
    return r;
  }
  SubmitOptions ignored;
  r.errors = take_server_fields(parsed.value, ignored);
  auto job = validate(std::move(parsed.value));
  r.errors.insert(r.errors.end(), job.errors.begin(), job.errors.end());
  if (!r.errors.empty()) {
    r.kind = CheckResult::Kind::invalid;
    return r;
  }
  r.validation = validation_json(*job.spec);
  r.spec = std::move(job.spec);
  return r;
}

SubmitResult JobService::submit(const std::string& body, const SubmitOptions& options) {
  auto parsed = api::parse_bounded_json(body);
  if (parsed.status == api::JsonParse::Status::syntax)
    return failure(Kind::bad_json, {parsed.error});
  if (!parsed.ok()) return failure(Kind::invalid, {parsed.error});
  return submit_document(std::move(parsed.value), options);
}

SubmitResult JobService::submit_document(nlohmann::json doc, const SubmitOptions& given) {
  SubmitOptions options = given;
  if (!doc.is_object()) return failure(Kind::invalid, {{"", "the job must be a JSON object"}});
  auto errors = take_server_fields(doc, options);
  auto parsed = validate(std::move(doc));
  errors.insert(errors.end(), parsed.errors.begin(), parsed.errors.end());
  if (!errors.empty()) return failure(Kind::invalid, std::move(errors));
  const api::JobSpec& spec = *parsed.spec;

  std::lock_guard lock(submit_mutex_);
  if (!options.idempotency_key.empty()) {
    if (auto earlier = store_.find_by_idempotency_key(options.user, options.idempotency_key)) {
      // The whole canonical request, as for studies: the spec with its name, tags and output
      // settings, and the submission's options. Only a retry of that request is a replay.
      if (earlier->spec != spec.canonical || earlier->fresh != options.fresh.value_or(false) ||
          earlier->priority != options.priority.value_or(0))
        return failure(Kind::key_conflict,
                       {{"", "Idempotency-Key " + options.idempotency_key +
                                 " was used for a different job (" + earlier->id + ")"}});
      SubmitResult r;
      r.kind = Kind::replayed;
      r.job = earlier;
      return r;
    }
  }

  Job job;
  job.id = new_job_id();
  job.name = spec.name;
  job.tags = spec.tags;
  job.spec = spec.canonical;
  job.spec_sha256 = spec.sha256;
  job.submitted_by = options.user;
  job.idempotency_key = options.idempotency_key;
  job.priority = options.priority.value_or(0);
  job.fresh = options.fresh.value_or(false);
  job.L = spec.params.friction.L;
  job.n_d = spec.params.geometry.nodes_per_meter;
  job.memory_estimate_bytes = spec.memory_estimate_bytes;
  job.created_at = now_iso8601();
  job.progress.duration = spec.params.time.duration;
  job.scene_hash = api::scene_hash(spec.canonical);
  job.study_id = options.study_id;
  job.validation = validation_json(spec);

  if (!job.fresh) {
    // A hit needs the same physics, code version and output settings: the file holds the
    // sampling, so another sampling is another file (docs/server.md, "Endpoints").
    auto earlier = store_.find_reusable(spec.sha256, options_.code_version,
                                        spec.canonical.value("output", nlohmann::json()),
                                        {options.user, options_.auth_enabled});
    if (earlier) {
      // Deleted by hand, lost or damaged: never point a new job at it; run the job again.
      auto file = result_files_.open(earlier->result);
      if (file.state != OpenedResult::State::intact) {
        log_error("job " + earlier->id + ": result file " + earlier->result.path + " is " +
                  (file.state == OpenedResult::State::missing ? "missing" : file.reason) +
                  "; identical jobs are run again instead of reusing it");
        earlier.reset();
      }
    }
    if (earlier) {
      job.status = JobStatus::succeeded;
      job.started_at = job.created_at;
      job.finished_at = job.created_at;
      job.progress = earlier->progress;
      job.code_version = earlier->code_version;
      job.host = earlier->host;
      job.wall_time_s = 0.0;
      job.result = earlier->result;
      job.cached_from = earlier->id;
      job.result_imported_by = earlier->result_imported_by;
      job.seq = store_.insert(job);
      SubmitResult r;
      r.kind = Kind::reused;
      r.job = store_.get(job.id);
      return r;
    }
  }

  if (!options.ignore_queue_limit && !queue_has_room()) return failure(Kind::queue_full, {});
  job.seq = store_.insert(job); // committed before the 201 is sent
  enqueue(job.id, job.priority, options.ignore_queue_limit);
  SubmitResult r;
  r.kind = Kind::created;
  r.job = job;
  return r;
}

bool JobService::queue_has_room() const {
  return queue_.size() + (batch_ ? batch_->size() : 0) < queue_.limit();
}

void JobService::enqueue(const std::string& id, int priority, bool ignore_queue_limit) {
  if (batch_) {
    batch_->push_back({id, priority});
    return;
  }
  // Pushes are serialised by submit_mutex_, so the queue has room; if it was closed
  // (draining), the job stays queued in the database and the next start-up runs it.
  if (ignore_queue_limit)
    queue_.push_unbounded(id, priority);
  else
    queue_.push(id, priority);
}

bool JobService::submit_together(const std::function<bool()>& f) {
  std::lock_guard lock(submit_mutex_);
  if (batch_) return f(); // already inside a batch: one transaction for both
  batch_.emplace();
  struct EndBatch {
    std::optional<std::vector<Pending>>& batch;
    ~EndBatch() { batch.reset(); }
  } end_batch{batch_};
  if (!store_.db().in_transaction(f)) return false;
  // Committed: every job of the batch was admitted against the limit, so each is queued
  // whatever happened to the queue meanwhile (a job committed as queued must be runnable).
  for (const auto& p : *batch_)
    queue_.push_unbounded(p.id, p.priority);
  return true;
}

std::optional<Job> JobService::get(const std::string& id) {
  auto job = store_.get(id);
  if (job && job->status == JobStatus::running)
    if (auto live = running_.progress(id)) job->progress = *live;
  return job;
}

JobPage JobService::list(const JobFilter& filter) {
  auto page = store_.list(filter);
  for (auto& job : page.jobs)
    if (job.status == JobStatus::running)
      if (auto live = running_.progress(job.id)) job.progress = *live;
  return page;
}

JobPage JobService::scan(const JobFilter& filter, const JobStore::EachJob& each) {
  return store_.scan(filter, [&](Job&& job, const std::string& convergence_status) {
    if (job.status == JobStatus::running)
      if (auto live = running_.progress(job.id)) job.progress = *live;
    each(std::move(job), convergence_status);
  });
}

CancelResult JobService::cancel(const std::string& id, const std::string& user) {
  auto job = store_.get(id);
  if (!job) return {CancelResult::Kind::not_found, std::nullopt};
  if (options_.auth_enabled && job->submitted_by != user)
    return {CancelResult::Kind::forbidden, job};
  if (is_final(job->status)) return {CancelResult::Kind::already_final, job};
  if (store_.cancel_queued(id, now_iso8601())) {
    queue_.remove(id);
    if (on_cancelled_) on_cancelled_(id);
    return {CancelResult::Kind::cancelled, store_.get(id)};
  }
  switch (running_.request_cancel(id, user)) {
  case RunningJobs::CancelRequest::requested:
    return {CancelResult::Kind::cancel_requested, get(id)};
  case RunningJobs::CancelRequest::finishing:
    return {CancelResult::Kind::finishing, get(id)};
  case RunningJobs::CancelRequest::not_running:
    break;
  }
  job = store_.get(id); // it finished in between
  return {CancelResult::Kind::already_final, job};
}

} // namespace slipfront::server
