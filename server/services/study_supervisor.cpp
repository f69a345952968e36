#include "server/services/study_supervisor.hpp"

#include "server/core/clock.hpp"
#include "server/core/log.hpp"
#include "server/services/study_progress.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
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
json search_json(const api::LSearch& search, const std::vector<double>& ladder, std::size_t active,
                 bool settled, const std::vector<api::StudyRun>& runs) {
  const auto v = api::search_verdict(search, ladder, active, settled, runs);
  return {{"state", api::to_string(v.state)},
          {"reason", v.reason},
          {"L_c", api::json_number(v.L_c)},
          {"next_L", api::json_number(v.next_L)},
          {"searched_L", std::vector<double>(ladder.begin(), ladder.begin() + active)},
          {"steps", v.steps},
          {"from", search.from},
          {"factor", search.factor},
          {"floor", search.floor},
          {"confirm", search.confirm}};
}

} // namespace

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
  if (!study) throw std::runtime_error("no study " + study_id + " in the database");
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
      const auto runs = study_runs(rows);
      for (std::size_t i = 0; i < active; ++i) {
        const double L = request.L[i];
        auto plan = api::refinement_plan(L, runs, request.n_d, request.n_d_max);
        json entry = {{"L", L},
                      {"state", api::to_string(plan.state)},
                      {"next_n_d", std::isfinite(plan.next_n_d) ? json(plan.next_n_d) : json()},
                      {"converged_n_d",
                       std::isfinite(plan.converged_n_d) ? json(plan.converged_n_d) : json()},
                      {"reason", plan.reason}};
        if (plan.state == api::RefinementPlan::State::waiting) plans_open = true;
        if (plan.state == api::RefinementPlan::State::run_next) {
          auto r = submit_study_run(jobs_, studies_, *study, request, json::object(), "", L,
                                    plan.next_n_d, true);
          if (r.job) {
            submitted = true;
            plans_open = true;
            entry["state"] = "waiting";
            entry["reason"] = "submitted n_d = " + number_text(plan.next_n_d) + " (job " +
                              r.job->id + "): " + plan.reason;
            log_info("study " + study_id + ": L = " + number_text(L) +
                     ": submitted n_d = " + number_text(plan.next_n_d) + " as job " + r.job->id);
          } else {
            entry["state"] = "submission_failed";
            entry["reason"] = "n_d = " + number_text(plan.next_n_d) + " refused: " +
                              (r.errors.empty() ? std::string("queue")
                                                : r.errors[0].pointer + " " + r.errors[0].reason);
            log_error("study " + study_id + ": " + entry["reason"].get<std::string>());
          }
        }
        refinement[json(L).dump()] = entry;
      }
      if (!submitted && !plans_open && request.search) {
        const auto verdict = api::search_verdict(*request.search, request.L, active, true, runs);
        if (verdict.state == api::SearchVerdict::State::next_L) {
          submitted = start_L(*study, request, verdict.next_L);
          ++active;
          log_info("study " + study_id + ": L search: " + verdict.reason);
        }
      }
      if (!submitted) break;
      rows = studies_.runs(study_id);
    }
    if (request.search)
      search = search_json(*request.search, request.L, active, !plans_open, study_runs(rows));
  }
  analyse_study(*study, rows, refinement, plans_open, now_iso8601());
  if (!search.is_null()) study->result["search"] = search;
  studies_.save_analysis(*study, rows);
  if (study->status == api::StudyStatus::finished && !study->finished_at.empty())
    log_info("study " + study_id + ": " + std::to_string(study->runs_total) + " run(s) finished");
}

} // namespace slipfront::server
