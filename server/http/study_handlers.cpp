// POST /studies, GET /studies, GET /studies/{id}, POST /studies/{id}/cancel (the owner's other
// changes: study_keep_handlers.cpp),
// GET /studies/{id}/speed-accuracy, GET /convergence-map (docs/studies-api.md).
#include "server/core/job_id.hpp"
#include "server/http/handlers.hpp"
#include "server/http/idempotency_key.hpp"
#include "server/http/job_filter_query.hpp" // parse_long
#include "server/http/responses.hpp"
#include "server/http/study_json.hpp"

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
  if (ctx.draining)
    return unavailable_response(req, "the server is shutting down", ctx.retry_after_s);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  std::vector<api::FieldError> header_errors;
  const std::string key = idempotency_key(req, header_errors);
  if (!header_errors.empty())
    return problem_response(req, http::status::bad_request, "invalid headers", header_errors);
  auto r = ctx.studies.create(req.body(), rc.user, key);
  using Kind = StudyCreateResult::Kind;
  switch (r.kind) {
  case Kind::bad_json:
    return problem_response(req, http::status::bad_request, "the body is not valid JSON", r.errors);
  case Kind::invalid:
    return problem_response(req, http::status::unprocessable_entity,
                            "the study request is invalid (" + std::to_string(r.errors.size()) +
                                " error" + (r.errors.size() == 1 ? "" : "s") + ")",
                            r.errors);
  case Kind::queue_full:
    return unavailable_response(req,
                                "the queue has no room for this study's runs (limit " +
                                    std::to_string(ctx.service.load().queue_limit) +
                                    " jobs); retry later",
                                ctx.retry_after_s);
  case Kind::key_conflict:
    return problem_response(req, http::status::unprocessable_entity,
                            r.errors.empty() ? "Idempotency-Key conflict" : r.errors[0].reason);
  case Kind::created:
  case Kind::replayed:
    break;
  }
  auto view = ctx.studies.view(*r.id);
  if (!view) throw std::runtime_error("study " + *r.id + " vanished after its creation");
  const bool replayed = r.kind == Kind::replayed;
  auto res =
      json_response(req, replayed ? http::status::ok : http::status::created, study_to_json(*view));
  res.set(http::field::location, api_prefix + "/studies/" + *r.id);
  if (replayed) res.set("Idempotent-Replayed", "true");
  return res;
}

Response get_study(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_study(rc.request, id);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto view = ctx.studies.view(id);
  if (!view) return not_found_study(rc.request, id);
  return json_response(rc.request, http::status::ok, study_to_json(*view));
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
  auto view = ctx.studies.view(id);
  if (!view) throw std::runtime_error("study " + id + " vanished while being cancelled");
  json body = study_to_json(*view);
  body["cancelled_jobs"] = r.cancelled_jobs;
  body["cancel_requested_jobs"] = r.cancel_requested_jobs;
  return json_response(rc.request,
                       r.cancel_requested_jobs.empty() ? http::status::ok : http::status::accepted,
                       body);
}

Response list_studies(ServerContext& ctx, RequestContext& rc) {
  if (auto bad = unknown_parameters(rc, {"limit", "cursor", "status", "archived"}))
    return std::move(*bad);
  std::vector<api::FieldError> errors;
  int limit = 50;
  std::optional<std::int64_t> cursor;
  std::optional<api::StudyStatus> status;
  if (auto it = rc.query.find("limit"); it != rc.query.end()) {
    auto l = parse_long(it->second);
    if (!l || *l < 1 || *l > 1000)
      errors.push_back({"/query/limit", "must be an integer in [1, 1000]"});
    else
      limit = static_cast<int>(*l);
  }
  if (auto it = rc.query.find("cursor"); it != rc.query.end()) {
    auto c = parse_long(it->second);
    if (!c || *c < 0)
      errors.push_back({"/query/cursor", "must be a cursor returned as next_cursor"});
    else
      cursor = *c;
  }
  if (auto it = rc.query.find("status"); it != rc.query.end()) {
    status = api::parse_study_status(it->second);
    if (!status) errors.push_back({"/query/status", "must be running, finished or cancelled"});
  }
  // Archived studies are left out unless asked for, as archived runs are.
  ArchivedRuns archived = ArchivedRuns::exclude;
  std::string archived_query;
  if (auto it = rc.query.find("archived"); it != rc.query.end()) {
    archived_query = "&archived=" + it->second;
    if (it->second == "include")
      archived = ArchivedRuns::include;
    else if (it->second == "only")
      archived = ArchivedRuns::only;
    else if (it->second != "exclude")
      errors.push_back({"/query/archived", "must be exclude (the default), include or only"});
  }
  if (!errors.empty())
    return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                            errors);
  auto studies = ctx.studies.list(limit + 1, cursor, status, archived);
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
                  archived_query + "&cursor=" + std::to_string(*next))
           : json(nullptr);
  return json_response(rc.request, http::status::ok, std::move(body));
}

// speed_accuracy of each regime, with the L2 error of the slip-velocity records (the service
// reads them from the result files).
Response speed_accuracy(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_study(rc.request, id);
  if (auto bad = unknown_parameters(rc, {})) return std::move(*bad);
  auto body = ctx.studies.speed_accuracy(id);
  if (!body) return not_found_study(rc.request, id);
  return json_response(rc.request, http::status::ok, std::move(*body));
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
    if (is_valid_job_id(study_id)) study = ctx.studies.get(study_id);
    if (!study) return not_found_study(rc.request, study_id);
    scene = study->scene_hash;
  } else {
    scene = scene_it->second;
    if (!is_hex64(scene))
      return problem_response(rc.request, http::status::bad_request, "invalid scene hash",
                              {{"/query/scene", "must be 64 lower-case hex characters"}});
  }
  auto body = ctx.studies.convergence_map(scene);
  body["scene_hash"] = scene;
  if (!study_id.empty()) body["study_id"] = study_id;
  body["source"] = "every succeeded or failed job with this scene hash, whoever submitted it "
                   "(reused copies are counted once, as their original)";
  return json_response(rc.request, http::status::ok, std::move(body));
}

} // namespace

void add_study_routes(Router& router, ServerContext& ctx) {
  router.add_json_body(http::verb::post, api_prefix + "/studies",
                       [&ctx](RequestContext& rc) { return create_study(ctx, rc); });
  router.add(
      http::verb::get, api_prefix + "/studies",
      [&ctx](RequestContext& rc) { return list_studies(ctx, rc); }, Runs::read_pool);
  router.add(http::verb::get, api_prefix + "/studies/{id}",
             [&ctx](RequestContext& rc) { return get_study(ctx, rc); });
  router.add(http::verb::post, api_prefix + "/studies/{id}/cancel",
             [&ctx](RequestContext& rc) { return cancel_study(ctx, rc); });
  router.add(
      http::verb::get, api_prefix + "/studies/{id}/speed-accuracy",
      [&ctx](RequestContext& rc) { return speed_accuracy(ctx, rc); }, Runs::read_pool);
  router.add(
      http::verb::get, api_prefix + "/convergence-map",
      [&ctx](RequestContext& rc) { return convergence_map(ctx, rc); }, Runs::read_pool);
}

} // namespace slipfront::server
