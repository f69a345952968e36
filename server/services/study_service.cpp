#include "server/services/study_service.hpp"

#include "api/json_number.hpp"
#include "server/core/clock.hpp"
#include "server/core/job_id.hpp"
#include "server/core/log.hpp"
#include "server/services/study_progress.hpp"

#include "api/job_spec.hpp"
#include "api/json_parse.hpp"
#include "api/study/failure_regimes.hpp"
#include "api/study_analysis.hpp"

#include <cmath>
#include <set>

namespace slipfront::server {

using nlohmann::json;

namespace {

using Kind = StudyCreateResult::Kind;

struct Planned {
  std::string regime;
  json overrides;
  double L;
  double n_d;
  bool submit_now;
};

// Every run the study may submit: for a convergence study the whole ladder up to the cap
// (checked now, so that a later mesh is not refused), submitted: the first two meshes.
std::vector<Planned> plan_runs(const StudyRequest& r) {
  std::vector<Planned> out;
  switch (r.kind) {
  case StudyKind::grid:
    for (double L : r.L)
      for (double n_d : r.n_d)
        out.push_back({"", json::object(), L, n_d, true});
    break;
  case StudyKind::convergence:
    for (double L : r.L) {
      int first = 0;
      for (double n_d : r.n_d)
        if (n_d <= r.n_d_max) out.push_back({"", json::object(), L, n_d, first++ < 2});
    }
    break;
  case StudyKind::failure_regimes:
    for (const auto& regime : api::failure_regimes())
      for (double n_d : regime.n_d)
        out.push_back({regime.name, regime.overrides, regime.L, n_d, true});
    break;
  }
  return out;
}

std::string value_pointer(const StudyRequest& r, const char* axis, double value) {
  const auto& values = std::string(axis) == "L" ? r.L : r.n_d;
  const std::string group = r.kind == StudyKind::convergence ? "/convergence/" : "/grid/";
  for (std::size_t i = 0; i < values.size(); ++i)
    if (values[i] == value) return group + axis + "/" + std::to_string(i);
  return "/preset";
}

// The job validator's errors for one run, with pointers into the study body.
void check_run(JobService& jobs, const StudyRequest& r, const Planned& p,
               std::vector<api::FieldError>& errors, std::set<std::string>& seen) {
  auto parsed =
      jobs.validate(run_document(r, std::string(32, '0'), p.overrides, p.regime, p.L, p.n_d));
  for (const auto& e : parsed.errors) {
    std::string pointer;
    if (e.pointer == "/friction/L")
      pointer = value_pointer(r, "L", p.L);
    else if (e.pointer == "/geometry/nodes_per_meter")
      pointer = value_pointer(r, "n_d", p.n_d);
    else
      pointer = "/base" + e.pointer;
    std::string reason = e.reason;
    if (!p.regime.empty()) reason += " (preset regime " + p.regime + ")";
    if (seen.insert(pointer + "\n" + reason).second) errors.push_back({pointer, reason});
  }
}

} // namespace

StudyCreateResult StudyService::create(const std::string& body, const std::string& user) {
  StudyCreateResult out;
  auto body_json = api::parse_bounded_json(body);
  if (!body_json.ok()) {
    out.kind = body_json.status == api::JsonParse::Status::syntax ? Kind::bad_json : Kind::invalid;
    out.errors.push_back(body_json.error);
    return out;
  }
  auto parsed = parse_study_request(body_json.value);
  if (!parsed.request) {
    out.kind = Kind::invalid;
    out.errors = std::move(parsed.errors);
    return out;
  }
  const StudyRequest& request = *parsed.request;
  const auto planned = plan_runs(request);
  std::set<std::string> seen;
  for (const auto& p : planned)
    check_run(jobs_, request, p, out.errors, seen);
  if (!out.errors.empty()) {
    out.kind = Kind::invalid;
    return out;
  }
  std::size_t now_count = 0;
  for (const auto& p : planned)
    now_count += p.submit_now ? 1 : 0;
  if (queue_.size() + now_count > queue_.limit()) {
    out.kind = Kind::queue_full;
    return out;
  }

  StudyRecord study;
  study.id = new_job_id();
  study.name = request.name;
  study.tags = request.tags;
  study.kind = to_string(request.kind);
  study.base = request.base;
  study.request = request.body;
  study.submitted_by = user;
  study.priority = request.priority.value_or(0);
  study.fresh = request.fresh.value_or(false);
  study.created_at = now_iso8601();
  // The scene of the base (for the preset: of its regularised runs).
  auto base = jobs_.validate(run_document(request, study.id, json::object(), "", 5e-5, 10));
  study.scene_hash = base.spec ? api::scene_hash(base.spec->canonical) : "";

  supervisor_.exclusive([&] {
    studies_.insert(study);
    for (const auto& p : planned) {
      if (!p.submit_now) continue;
      auto r = submit_study_run(jobs_, studies_, study, request, p.overrides, p.regime, p.L, p.n_d,
                                true);
      if (!r.job)
        log_error("study " + study.id + ": a run was refused after validation: " +
                  (r.errors.empty() ? "" : r.errors[0].pointer + " " + r.errors[0].reason));
    }
    supervisor_.step_locked(study.id);
  });
  log_info("study " + study.id + " created (" + study.kind + ", " + std::to_string(now_count) +
           " run(s) submitted) by " + user);
  out.id = study.id;
  return out;
}

StudyCancelResult StudyService::cancel(const std::string& id, const std::string& user,
                                       bool auth_enabled) {
  using CancelKind = StudyCancelResult::Kind;
  StudyCancelResult out;
  supervisor_.exclusive([&] {
    auto study = studies_.get(id);
    if (!study) {
      out.kind = CancelKind::not_found;
      return;
    }
    out.status = study->status;
    if (auth_enabled && study->submitted_by != user) {
      out.kind = CancelKind::forbidden;
      return;
    }
    if (study->status != api::StudyStatus::running) {
      out.kind = CancelKind::already_over;
      return;
    }
    // Cancelled first, under the step lock: no step can submit a further mesh after this.
    studies_.set_status(id, api::StudyStatus::cancelled, now_iso8601());
    auto runs = supervisor_.cancel_runs_locked(*study);
    out.cancelled_jobs = std::move(runs.cancelled);
    out.cancel_requested_jobs = std::move(runs.cancel_requested);
    try {
      supervisor_.step_locked(id);
    } catch (const std::exception& e) { // stored again when its runs end
      log_error("study " + id + ": analysis after the cancel: " + e.what());
    }
  });
  if (out.kind == CancelKind::cancelled)
    log_info("study " + id + " cancelled (" + std::to_string(out.cancelled_jobs.size()) +
             " queued job(s) cancelled, " + std::to_string(out.cancel_requested_jobs.size()) +
             " running job(s) asked to stop)");
  return out;
}

std::optional<MethodScenes> StudyService::method_scenes(const StudyRecord& study) {
  StudyRequest request;
  request.base = study.base;
  auto base = jobs_.validate(run_document(request, study.id, json::object(), "", 5e-5, 10));
  if (!base.spec) return std::nullopt;
  return MethodScenes{base.spec->params.method == Method::finite_element, study.scene_hash,
                      api::counterpart_scene_hash(base.spec->canonical)};
}

std::optional<json> StudyService::view(const std::string& id) {
  auto study = studies_.get(id);
  if (!study) return std::nullopt;
  json j = study_to_json(*study, studies_.runs(id));
  // The same scene by the other method, from every run the group has made of it.
  if (const auto scenes = method_scenes(*study)) {
    j["counterpart_scene_hash"] =
        scenes->other_scene.empty() ? json(nullptr) : json(scenes->other_scene);
    if (!scenes->other_scene.empty()) {
      const auto mine = studies_.scene_runs(scenes->scene);
      const auto theirs = studies_.scene_runs(scenes->other_scene);
      j["cross_method"] = scenes->is_fe ? cross_method(mine, theirs) : cross_method(theirs, mine);
    }
  }
  return j;
}

json study_to_json(const StudyRecord& s, const std::vector<StudyRunRow>& runs, bool summary) {
  const std::string self = "/api/v1/studies/" + s.id;
  json j;
  j["id"] = s.id;
  j["name"] = s.name;
  j["tags"] = s.tags;
  j["kind"] = s.kind;
  j["status"] = api::to_string(s.status);
  j["submitted_by"] = s.submitted_by;
  j["created_at"] = s.created_at;
  j["updated_at"] = s.updated_at.empty() ? json(nullptr) : json(s.updated_at);
  j["finished_at"] = s.finished_at.empty() ? json(nullptr) : json(s.finished_at);
  j["scene_hash"] = s.scene_hash;
  j["method"] = s.base.is_object() ? s.base.value("method", "fe") : "fe";
  j["progress"] = {{"done", s.runs_done},
                   {"total", s.runs_total},
                   {"fraction", s.runs_total ? double(s.runs_done) / s.runs_total : 0.0}};
  j["L_c"] = api::json_number(s.L_c);
  j["spectral_critical_length"] = api::json_number(s.spectral_critical_length);
  j["links"] = {{"self", self},
                {"speed_accuracy", self + "/speed-accuracy"},
                {"convergence_map", "/api/v1/convergence-map?scene=" + s.scene_hash},
                {"jobs", "/api/v1/jobs?study_id=" + s.id}};
  if (summary) return j;
  j["request"] = s.request;
  json list = json::array();
  for (const auto& r : runs) {
    std::string outcome;
    if (r.metrics.is_object() && r.metrics.contains("outcome") && r.metrics["outcome"].is_string())
      outcome = r.metrics["outcome"].get<std::string>();
    json run = {{"job_id", r.job_id},
                {"L", r.L},
                {"n_d", r.n_d},
                {"job_status", r.job_status},
                {"outcome", outcome.empty() ? json(nullptr) : json(outcome)},
                {"cached_from", r.cached_from.empty() ? json(nullptr) : json(r.cached_from)},
                {"error", r.error.empty() ? json(nullptr) : json(r.error)},
                {"convergence",
                 {{"status", r.convergence_status},
                  {"partner_n_d", api::json_number(r.partner_n_d)},
                  {"changes",
                   {{"propagation_distance", api::json_number(r.propagation_distance_change)},
                    {"arrival_time", api::json_number(r.arrival_time_change)}}},
                  {"reason", r.reason}}},
                {"links", {{"job", "/api/v1/jobs/" + r.job_id}}}};
    if (!r.regime.empty()) run["regime"] = r.regime;
    list.push_back(std::move(run));
  }
  j["runs"] = list;
  const json& result = s.result.is_object() ? s.result : json::object();
  j["critical_length"] = result.value("critical_length", json(nullptr));
  j["convergence_map"] = result.value("convergence_map", json(nullptr));
  if (result.contains("refinement")) j["refinement"] = result["refinement"];
  if (result.contains("regimes")) j["regimes"] = result["regimes"];
  return j;
}

} // namespace slipfront::server
