// POST /studies, GET /studies, GET /studies/{id}, POST /studies/{id}/cancel,
// GET /studies/{id}/speed-accuracy, GET /convergence-map (docs/studies-api.md).
#include "server/core/job_id.hpp"
#include "server/http/handlers.hpp"
#include "server/http/responses.hpp"
#include "server/services/study_progress.hpp"

#include "api/json_number.hpp"
#include "api/result_reader.hpp"
#include "api/study_analysis.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace slipfront::server {

namespace {

using nlohmann::json;

Response not_found_study(const Request& req, const std::string& id) {
  return problem_response(req, http::status::not_found, "no study with id " + id);
}

std::optional<Response> unknown_parameters(const RequestContext& rc,
                                           const std::set<std::string>& known) {
  std::vector<api::FieldError> errors;
  for (const auto& [key, value] : rc.query)
    if (!known.count(key)) errors.push_back({"/query/" + key, "unknown query parameter"});
  if (errors.empty()) return std::nullopt;
  return Response(
      problem_response(rc.request, http::status::bad_request, "invalid query parameters", errors));
}

Response create_study(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& req = rc.request;
  if (ctx.draining) {
    auto res =
        problem_response(req, http::status::service_unavailable, "the server is shutting down");
    res.set(http::field::retry_after, std::to_string(ctx.retry_after_s));
    return res;
  }
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto r = ctx.studies.create(req.body(), rc.user);
  using Kind = StudyCreateResult::Kind;
  switch (r.kind) {
  case Kind::bad_json:
    return problem_response(req, http::status::bad_request, "the body is not valid JSON", r.errors);
  case Kind::invalid:
    return problem_response(req, http::status::unprocessable_entity,
                            "the study request is invalid (" + std::to_string(r.errors.size()) +
                                " error" + (r.errors.size() == 1 ? "" : "s") + ")",
                            r.errors);
  case Kind::queue_full: {
    auto res = problem_response(req, http::status::service_unavailable,
                                "the queue has no room for this study's runs (limit " +
                                    std::to_string(ctx.service.load().queue_limit) +
                                    " jobs); retry later");
    res.set(http::field::retry_after, std::to_string(ctx.retry_after_s));
    return res;
  }
  case Kind::created:
    break;
  }
  auto body = ctx.studies.view(*r.id);
  if (!body) throw std::runtime_error("study " + *r.id + " vanished after its creation");
  auto res = json_response(req, http::status::created, *body);
  res.set(http::field::location, api_prefix + "/studies/" + *r.id);
  return res;
}

Response get_study(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_study(rc.request, id);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto body = ctx.studies.view(id);
  if (!body) return not_found_study(rc.request, id);
  return json_response(rc.request, http::status::ok, *body);
}

// 200 when every unfinished run was still queued (all cancelled now), 202 when running
// runs were asked to stop and will report `cancelled` when they do.
Response cancel_study(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_study(rc.request, id);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto r = ctx.studies.cancel(id, rc.user, ctx.tokens.has_value());
  using Kind = StudyCancelResult::Kind;
  switch (r.kind) {
  case Kind::not_found:
    return not_found_study(rc.request, id);
  case Kind::forbidden:
    return problem_response(rc.request, http::status::forbidden,
                            "study " + id + " was submitted by another user");
  case Kind::already_over:
    return problem_response(rc.request, http::status::conflict,
                            "study " + id + " is already " + api::to_string(r.status));
  case Kind::cancelled:
    break;
  }
  auto body = ctx.studies.view(id);
  if (!body) throw std::runtime_error("study " + id + " vanished while being cancelled");
  (*body)["cancelled_jobs"] = r.cancelled_jobs;
  (*body)["cancel_requested_jobs"] = r.cancel_requested_jobs;
  return json_response(rc.request,
                       r.cancel_requested_jobs.empty() ? http::status::ok : http::status::accepted,
                       *body);
}

Response list_studies(ServerContext& ctx, RequestContext& rc) {
  if (auto bad = unknown_parameters(rc, {"limit", "cursor", "status"})) return std::move(*bad);
  std::vector<api::FieldError> errors;
  int limit = 50;
  std::optional<std::int64_t> cursor;
  std::optional<api::StudyStatus> status;
  auto integer = [](const std::string& s) -> std::optional<long> {
    long v = 0;
    auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
    return v;
  };
  if (auto it = rc.query.find("limit"); it != rc.query.end()) {
    auto l = integer(it->second);
    if (!l || *l < 1 || *l > 1000)
      errors.push_back({"/query/limit", "must be an integer in [1, 1000]"});
    else
      limit = static_cast<int>(*l);
  }
  if (auto it = rc.query.find("cursor"); it != rc.query.end()) {
    auto c = integer(it->second);
    if (!c || *c < 0)
      errors.push_back({"/query/cursor", "must be a cursor returned as next_cursor"});
    else
      cursor = *c;
  }
  if (auto it = rc.query.find("status"); it != rc.query.end()) {
    status = api::parse_study_status(it->second);
    if (!status) errors.push_back({"/query/status", "must be running, finished or cancelled"});
  }
  if (!errors.empty())
    return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                            errors);
  auto studies = ctx.studies.store().list(limit + 1, cursor, status);
  json body;
  body["studies"] = json::array();
  std::optional<std::int64_t> next;
  for (const auto& s : studies) {
    if (static_cast<int>(body["studies"].size()) == limit) {
      next = body["studies"].empty() ? 0 : studies[static_cast<std::size_t>(limit) - 1].seq;
      break;
    }
    body["studies"].push_back(study_to_json(s, {}, true));
  }
  body["count"] = body["studies"].size();
  body["next_cursor"] = next ? json(std::to_string(*next)) : json(nullptr);
  body["next"] =
      next ? json(api_prefix + "/studies?limit=" + std::to_string(limit) +
                  (status ? std::string("&status=") + api::to_string(*status) : std::string()) +
                  "&cursor=" + std::to_string(*next))
           : json(nullptr);
  return json_response(rc.request, http::status::ok, body);
}

// speed_accuracy of each regime, with the relative L2 error of the slip-velocity record at
// the spectrum probe against the reference run's record (api/study/speed_accuracy.hpp);
// the records are read from the result files here.
Response speed_accuracy(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_study(rc.request, id);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto study = ctx.studies.store().get(id);
  if (!study) return not_found_study(rc.request, id);
  auto rows = ctx.studies.store().runs(id);
  std::map<std::string, const StudyRunRow*> by_id;
  std::vector<api::RegimeRun> runs;
  for (const auto& r : rows) {
    runs.push_back({r.regime, to_study_run(r)});
    by_id[r.job_id] = &r;
  }
  // The slip-velocity record at the spectrum probe, from the run's result file.
  api::SlipVelocityErrors l2([&](const std::string& job_id, std::string& why) {
    const auto* row = by_id.at(job_id);
    std::optional<api::ProbeSeries> series;
    if (row->result_path.empty()) {
      why = "no result file (job " + row->job_status + ")";
    } else if (auto rec = api::read_probe_record(ctx.data_dir + "/" + row->result_path, why)) {
      series = api::ProbeSeries{std::move(rec->time), std::move(rec->slip_velocity), rec->x1};
    }
    return series;
  });
  json list = api::speed_accuracy_by_regime(runs, l2);
  // Both methods on one chart: every run of the study's scene and of its counterpart.
  json across = nullptr;
  std::vector<StudyRunRow> scene_rows;
  if (const auto scenes = ctx.studies.method_scenes(*study);
      scenes && !scenes->other_scene.empty()) {
    scene_rows = ctx.studies.store().scene_runs(scenes->scene);
    const std::size_t own = scene_rows.size();
    auto other_rows = ctx.studies.store().scene_runs(scenes->other_scene);
    scene_rows.insert(scene_rows.end(), other_rows.begin(), other_rows.end());
    std::vector<api::StudyRun> mine, theirs;
    for (std::size_t k = 0; k < scene_rows.size(); ++k) {
      by_id.emplace(scene_rows[k].job_id, &scene_rows[k]);
      (k < own ? mine : theirs).push_back(to_study_run(scene_rows[k]));
    }
    json across_runs = scenes->is_fe ? api::speed_accuracy_across_methods(mine, theirs)
                                     : api::speed_accuracy_across_methods(theirs, mine);
    for (auto& entry : across_runs)
      l2.add_to(entry);
    across = {{"runs", across_runs},
              {"reference", "the finest reference run of the same L by either method "
                            "(spectral_bi on a tie), from every run of the two scenes"}};
  }
  json body = {{"study_id", id},
               {"runs", list},
               {"probe",
                {{"dataset", "/probes/slip_velocity_spectrum"},
                 {"x1", api::json_number(l2.probe_x1())},
                 {"description", "relative L2 error over time of the slip velocity at the "
                                 "spectrum probe (probe.spectrum_x1, default 6 m)"}}},
               {"reference", "the finest non-diverged run of the same L, when that L has a "
                             "mesh-converged run (docs/studies.md)"},
               {"across_methods", across}};
  return json_response(rc.request, http::status::ok, body);
}

bool is_hex64(const std::string& s) {
  if (s.size() != 64) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

Response convergence_map(ServerContext& ctx, RequestContext& rc) {
  if (auto bad = unknown_parameters(rc, {"scene", "study"})) return std::move(*bad);
  const auto scene_it = rc.query.find("scene");
  const auto study_it = rc.query.find("study");
  if ((scene_it == rc.query.end()) == (study_it == rc.query.end()))
    return problem_response(rc.request, http::status::bad_request,
                            "give exactly one of scene=<scene_hash> or study=<study id>",
                            {{"/query/scene", "or /query/study: exactly one is required"}});
  std::string scene;
  std::string study_id;
  if (study_it != rc.query.end()) {
    study_id = study_it->second;
    std::optional<StudyRecord> study;
    if (is_valid_job_id(study_id)) study = ctx.studies.store().get(study_id);
    if (!study) return not_found_study(rc.request, study_id);
    scene = study->scene_hash;
  } else {
    scene = scene_it->second;
    if (!is_hex64(scene))
      return problem_response(rc.request, http::status::bad_request, "invalid scene hash",
                              {{"/query/scene", "must be 64 lower-case hex characters"}});
  }
  auto body = scene_analysis(ctx.studies.store().scene_runs(scene));
  body["scene_hash"] = scene;
  if (!study_id.empty()) body["study_id"] = study_id;
  body["source"] = "every succeeded or failed job with this scene hash, whoever submitted it "
                   "(reused copies are counted once, as their original)";
  return json_response(rc.request, http::status::ok, body);
}

} // namespace

void add_study_routes(Router& router, ServerContext& ctx) {
  router.add(http::verb::post, api_prefix + "/studies",
             [&ctx](RequestContext& rc) { return create_study(ctx, rc); });
  router.add(
      http::verb::get, api_prefix + "/studies",
      [&ctx](RequestContext& rc) { return list_studies(ctx, rc); }, true);
  router.add(http::verb::get, api_prefix + "/studies/{id}",
             [&ctx](RequestContext& rc) { return get_study(ctx, rc); });
  router.add(http::verb::post, api_prefix + "/studies/{id}/cancel",
             [&ctx](RequestContext& rc) { return cancel_study(ctx, rc); });
  router.add(
      http::verb::get, api_prefix + "/studies/{id}/speed-accuracy",
      [&ctx](RequestContext& rc) { return speed_accuracy(ctx, rc); }, true);
  router.add(
      http::verb::get, api_prefix + "/convergence-map",
      [&ctx](RequestContext& rc) { return convergence_map(ctx, rc); }, true);
}

} // namespace slipfront::server
