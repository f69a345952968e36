#include "server/services/study_supervisor.hpp"

#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/services/study_progress.hpp"

#include "api/job_methods.hpp"
#include "api/job_spec.hpp"
#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "api/study/accuracy_target.hpp"
#include "api/study/l_search.hpp"
#include "api/study/run_rules.hpp"

namespace slipfront::server {

using nlohmann::json;

SubmitResult submit_study_run(JobService& jobs, StudyStore& studies, const StudyRecord& study,
                              const StudyRequest& request, const json& overrides,
                              const std::string& regime, double L, double n_d,
                              bool ignore_queue_limit) {
  SubmitOptions options;
  options.user = study.submitted_by;
  options.fresh = request.fresh;
  options.priority = request.priority;
  options.study_id = study.id;
  options.ignore_queue_limit = ignore_queue_limit;
  auto r =
      jobs.submit_document(run_document(request, study.id, overrides, regime, L, n_d), options);
  if (r.job) studies.add_run(study.id, r.job->id, regime, L, n_d);
  return r;
}

StudySupervisor::StudySupervisor(StudyStore& studies, JobService& jobs)
    : studies_(studies), jobs_(jobs) {}

StudySupervisor::~StudySupervisor() {
  stop();
}

void StudySupervisor::start() {
  for (const auto& id : studies_.running_ids())
    request_step(id);
  // A run of a cancelled study that was still stopping when the server went down is queued
  // again by the recovery: cancel it before any worker starts, and store the final analysis.
  for (const auto& id : studies_.unsettled_cancelled_ids()) {
    exclusive([&] {
      if (auto study = studies_.get(id)) cancel_runs_locked(*study);
    });
    request_step(id);
  }
  thread_ = std::thread([this] { loop(); });
}

CancelledRuns StudySupervisor::cancel_runs_locked(const StudyRecord& study) {
  CancelledRuns out;
  for (const auto& run : studies_.runs(study.id)) {
    auto status = parse_status(run.job_status);
    if (status && is_final(*status)) continue;
    try {
      // The study's jobs were submitted under its submitter's name (submit_study_run).
      auto r = jobs_.cancel(run.job_id, study.submitted_by);
      if (r.kind == CancelResult::Kind::cancelled) out.cancelled.push_back(run.job_id);
      if (r.kind == CancelResult::Kind::cancel_requested)
        out.cancel_requested.push_back(run.job_id);
    } catch (const std::exception& e) {
      log_error("study " + study.id + ": cancelling its job " + run.job_id + ": " + e.what());
    }
  }
  return out;
}

void StudySupervisor::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void StudySupervisor::job_finished(const std::string& job_id) {
  try {
    auto study = studies_.study_of_job(job_id);
    if (!study.empty()) request_step(study);
  } catch (const std::exception& e) {
    log_error("study supervisor: looking up the study of job " + job_id + ": " + e.what());
  }
}

void StudySupervisor::request_step(const std::string& study_id) {
  {
    std::lock_guard lock(mutex_);
    if (!queued_.insert(study_id).second) return;
    pending_.push_back(study_id);
  }
  wake_.notify_one();
}

void StudySupervisor::loop() {
  for (;;) {
    std::string id;
    {
      std::unique_lock lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || !pending_.empty(); });
      if (stopping_) return;
      id = pending_.front();
      pending_.pop_front();
      queued_.erase(id);
    }
    try {
      exclusive([&] { step_locked(id); });
    } catch (const std::exception& e) {
      log_error("study " + id + ": step failed: " + e.what());
    }
  }
}

namespace {

using api::number_text;

// The last plan of a cancelled convergence study, each L that was waiting marked cancelled.
json cancelled_refinement(const json& result) {
  json plan = result.is_object() ? result.value("refinement", json::object()) : json::object();
  for (auto& entry : plan) {
    if (!entry.is_object() || entry.value("state", "") != "waiting") continue;
    entry["state"] = "cancelled";
    entry["reason"] = "study cancelled; " + entry.value("reason", std::string());
  }
  return plan;
}

std::vector<api::StudyRun> study_runs(const std::vector<StudyRunRow>& rows) {
  std::vector<api::StudyRun> runs;
  for (const auto& r : rows)
    runs.push_back(to_study_run(r));
  return runs;
}

// The runs of one regime ("" the study's own L, coulomb_regime an L search's Coulomb runs).
std::vector<api::StudyRun> regime_runs(const std::vector<StudyRunRow>& rows,
                                       const std::string& regime) {
  std::vector<api::StudyRun> runs;
  for (const auto& r : rows)
    if (r.regime == regime) runs.push_back(to_study_run(r));
  return runs;
}

// An L search's plain-Coulomb reference; `coulomb_runs` must outlive it.
api::CoulombReference search_coulomb(const StudyRequest& r,
                                     const std::vector<api::StudyRun>& coulomb_runs) {
  if (!r.search || !r.search->coulomb.value_or(false)) return {};
  return api::coulomb_reference(r.search->from, coulomb_runs, r.n_d, r.n_d_max);
}

// How many L of an L search's ladder have runs: they are started in the ladder's order.
std::size_t started_L(const std::vector<double>& ladder, const std::vector<StudyRunRow>& rows) {
  std::size_t started = 1;
  for (std::size_t i = 0; i < ladder.size(); ++i)
    for (const auto& row : rows)
      if (row.regime.empty() && api::study_rules::same_value(row.L, ladder[i]))
        started = std::max(started, i + 1);
  return started;
}

// The search's state for the reader (docs/studies-api.md "L search").
json search_json(const StudyRequest& r, std::size_t active, bool settled,
                 const std::vector<StudyRunRow>& rows) {
  const api::LSearch& search = *r.search;
  const std::vector<double>& ladder = r.L;
  const auto coulomb_runs = regime_runs(rows, coulomb_regime);
  const auto v = api::search_verdict(search, ladder, active, settled, regime_runs(rows, ""),
                                     search_coulomb(r, coulomb_runs));
  return {{"state", api::to_string(v.state)},
          {"reason", v.reason},
          {"L_c", api::json_number(v.L_c)},
          {"next_L", api::json_number(v.next_L)},
          {"searched_L", std::vector<double>(ladder.begin(), ladder.begin() + active)},
          {"steps", v.steps},
          {"coulomb", v.coulomb},
          {"from", search.from},
          {"factor", search.factor},
          {"floor", search.floor},
          {"confirm", search.confirm}};
}

// Why an accuracy study runs the method it runs (the service chose it when "auto": the
// cheapest that applies, api::cheaper_methods, else the default).
std::string method_reason(const StudyRequest& r, JobService& jobs, const std::string& study_id) {
  if (r.method_choice != "auto") return "asked for (accuracy.method)";
  const MethodEntry* method = find_method(api::method_name_of(r.base));
  const MethodEntry& fallback = default_method();
  if (method != nullptr && method != &fallback)
    return std::string("chosen by the service: the scene is a ") +
           (method->supports.block_height ? "block" : "half-space") + " problem the " +
           method->heading + " method solves, at less cost than " + fallback.heading +
           " at the same n_d";
  std::string first_error;
  for (const MethodEntry* cheaper : api::cheaper_methods()) {
    StudyRequest trial = r;
    trial.base = api::method_document(r.base, *cheaper);
    const auto tried =
        jobs.validate(run_document(trial, study_id, json::object(), "", r.L[0], r.n_d[0]));
    if (tried.spec) return "named by the base (/base/method)";
    if (first_error.empty())
      first_error =
          std::string("the ") + cheaper->heading + " method cannot run this scene (" +
          (tried.errors.empty() ? std::string("invalid")
                                : tried.errors[0].pointer + " " + tried.errors[0].reason) +
          ")";
  }
  if (first_error.empty()) return "named by the base (/base/method)";
  return "chosen by the service: " + first_error;
}

} // namespace

json StudySupervisor::accuracy_step(const StudyRecord& study, const StudyRequest& request,
                                    std::vector<StudyRunRow>& rows, bool may_submit,
                                    bool& plans_open) {
  const auto& target = *request.accuracy;
  const std::size_t first = request.accuracy_start.value_or(0);
  api::AccuracyVerdict v;
  // Each pass submits at most one mesh; a reused result can settle it at once, so repeat.
  for (std::size_t pass = 0; pass <= request.n_d.size(); ++pass) {
    v = api::accuracy_verdict(target, request.n_d, first, request.n_d_max, study_runs(rows));
    if (v.state != api::AccuracyVerdict::State::run_next || !may_submit) break;
    auto r = submit_study_run(jobs_, studies_, study, request, json::object(), "", target.L,
                              v.next_n_d, true);
    if (!r.job) {
      v.state = api::AccuracyVerdict::State::failed;
      v.reason = "n_d = " + number_text(v.next_n_d) + " refused: " +
                 (r.errors.empty() ? std::string("queue")
                                   : r.errors[0].pointer + " " + r.errors[0].reason);
      log_error("study " + study.id + ": " + v.reason);
      break;
    }
    log_info("study " + study.id + ": accuracy: submitted n_d = " + number_text(v.next_n_d) +
             " as job " + r.job->id);
    rows = studies_.runs(study.id);
  }
  plans_open = may_submit && (v.state == api::AccuracyVerdict::State::waiting ||
                              v.state == api::AccuracyVerdict::State::run_next);
  if (!may_submit && v.state == api::AccuracyVerdict::State::run_next)
    v.reason = "study cancelled; " + v.reason;
  double wall = 0.0;
  for (const auto& run : study_runs(rows))
    wall += run.wall_time_s;
  json out = api::to_json(v);
  out["target"] = {{"metric", target.metric}, {"tolerance", target.tolerance}, {"L", target.L}};
  out["method"] = {{"name", api::method_name_of(request.base)},
                   {"reason", method_reason(request, jobs_, study.id)}};
  const json& start = request.body["accuracy"];
  out["start"] = start.contains("start") ? start["start"] : json(nullptr);
  out["cost"] = {{"runs", rows.size()},
                 {"wall_time_s", wall},
                 {"description", "the study's runs, each by its own wall time (a reused result "
                                 "by the time it took when it was computed)"}};
  return out;
}

// The first two meshes (up to the cap) of the next L of a search; whether one was submitted.
bool StudySupervisor::start_L(const StudyRecord& study, const StudyRequest& request, double L) {
  bool submitted = false;
  int count = 0;
  for (double n_d : request.n_d) {
    if (n_d > request.n_d_max || count++ >= 2) break;
    auto r = submit_study_run(jobs_, studies_, study, request, json::object(), "", L, n_d, true);
    if (r.job) {
      submitted = true;
      log_info("study " + study.id + ": L = " + number_text(L) +
               ": submitted n_d = " + number_text(n_d) + " as job " + r.job->id);
    } else {
      log_error("study " + study.id + ": L = " + number_text(L) + ", n_d = " + number_text(n_d) +
                " refused: " +
                (r.errors.empty() ? std::string("queue")
                                  : r.errors[0].pointer + " " + r.errors[0].reason));
    }
  }
  return submitted;
}

void StudySupervisor::step_locked(const std::string& study_id) {
  auto study = studies_.get(study_id);
  if (!study) return; // deleted meanwhile (DELETE /studies/{id}): nothing left to step
  auto parsed = parse_study_request(study->request);
  if (!parsed.request)
    throw std::runtime_error(
        "stored request of study " + study_id + " no longer parses: " +
        (parsed.errors.empty() ? "" : parsed.errors[0].pointer + " " + parsed.errors[0].reason));
  const StudyRequest& request = *parsed.request;
  auto rows = studies_.runs(study_id);
  json refinement = nullptr;
  json search = nullptr;
  bool plans_open = false;
  if (study->kind == "convergence" && study->status == api::StudyStatus::cancelled) {
    refinement = cancelled_refinement(study->result);
  } else if (study->kind == "convergence") {
    // Each pass submits at most one mesh per L (and an L search at most its next L); a reused
    // result can settle a plan at once, so repeat (bounded by the meshes and L it may submit).
    std::size_t active = request.search ? started_L(request.L, rows) : request.L.size();
    const std::size_t passes = (request.n_d.size() + 1) * (request.L.size() + 1);
    for (std::size_t pass = 0; pass < passes; ++pass) {
      refinement = json::object();
      plans_open = false;
      bool submitted = false;
      const auto runs = regime_runs(rows, "");
      const auto coulomb_runs = regime_runs(rows, coulomb_regime);
      const bool with_coulomb = request.search && request.search->coulomb.value_or(false);
      for (std::size_t i = 0; i < active + (with_coulomb ? 1 : 0); ++i) {
        // The L in order; an L search's plain-Coulomb runs last, refined like one more L.
        const bool coulomb = i == active;
        const double L = coulomb ? request.search->from : request.L[i];
        const std::string regime = coulomb ? coulomb_regime : "";
        auto plan =
            api::refinement_plan(L, coulomb ? coulomb_runs : runs, request.n_d, request.n_d_max);
        json entry = {{"L", L},
                      {"state", api::to_string(plan.state)},
                      {"next_n_d", std::isfinite(plan.next_n_d) ? json(plan.next_n_d) : json()},
                      {"converged_n_d",
                       std::isfinite(plan.converged_n_d) ? json(plan.converged_n_d) : json()},
                      {"reason", plan.reason}};
        if (plan.state == api::RefinementPlan::State::waiting) plans_open = true;
        if (plan.state == api::RefinementPlan::State::run_next) {
          auto r = submit_study_run(jobs_, studies_, *study, request,
                                    coulomb ? coulomb_overrides(request.base) : json::object(),
                                    regime, L, plan.next_n_d, true);
          if (r.job) {
            submitted = true;
            plans_open = true;
            entry["state"] = "waiting";
            entry["reason"] = "submitted n_d = " + number_text(plan.next_n_d) + " (job " +
                              r.job->id + "): " + plan.reason;
            log_info("study " + study_id + ": " + (coulomb ? "Coulomb" : "L = " + number_text(L)) +
                     ": submitted n_d = " + number_text(plan.next_n_d) + " as job " + r.job->id);
          } else {
            entry["state"] = "submission_failed";
            entry["reason"] = "n_d = " + number_text(plan.next_n_d) + " refused: " +
                              (r.errors.empty() ? std::string("queue")
                                                : r.errors[0].pointer + " " + r.errors[0].reason);
            log_error("study " + study_id + ": " + entry["reason"].get<std::string>());
          }
        }
        if (coulomb) entry["regime"] = coulomb_regime;
        refinement[coulomb ? std::string(coulomb_regime) : json(L).dump()] = entry;
      }
      if (!submitted && !plans_open && request.search) {
        const auto verdict = api::search_verdict(*request.search, request.L, active, true, runs,
                                                 search_coulomb(request, coulomb_runs));
        if (verdict.state == api::SearchVerdict::State::next_L) {
          submitted = start_L(*study, request, verdict.next_L);
          ++active;
          log_info("study " + study_id + ": L search: " + verdict.reason);
        }
      }
      if (!submitted) break;
      rows = studies_.runs(study_id);
    }
    if (request.search) search = search_json(request, active, !plans_open, rows);
  } else if (study->kind == "accuracy") {
    search = accuracy_step(*study, request, rows, study->status != api::StudyStatus::cancelled,
                           plans_open);
  }
  analyse_study(*study, rows, refinement, plans_open, now_iso8601());
  if (!search.is_null()) study->result[study->kind == "accuracy" ? "accuracy" : "search"] = search;
  studies_.save_analysis(*study, rows);
  if (study->status == api::StudyStatus::finished && !study->finished_at.empty())
    log_info("study " + study_id + ": " + std::to_string(study->runs_total) + " run(s) finished");
}

} // namespace slipfront::server
