// What an owner does with a study after creating it (docs/server.md "Keep, annotate, share"):
// PATCH /studies/{id} (tags added, removed or replaced; note), POST /studies/{id}/archive and
// /restore, DELETE /studies/{id} with its runs. With a token file, only the user who created
// the study may (as for its cancel).
#include "api/json_parse.hpp"
#include "api/run_annotations.hpp"
#include "server/core/job_id.hpp"
#include "server/http/handlers.hpp"
#include "server/http/responses.hpp"
#include "server/http/study_json.hpp"

namespace slipfront::server {

namespace {

using nlohmann::json;

// The refusals every change shares; nullopt when it was done.
std::optional<Response> refusal(const Request& req, const std::string& id,
                                const StudyKeepResult& r) {
  using Kind = StudyKeepResult::Kind;
  switch (r.kind) {
  case Kind::done:
    return std::nullopt;
  case Kind::not_found:
    return problem_response(req, http::status::not_found, "no study with id " + id);
  case Kind::forbidden:
    return problem_response(req, http::status::forbidden,
                            "study " + id +
                                " was submitted by another user: only its owner may change it");
  case Kind::running:
    return problem_response(req, http::status::conflict,
                            "study " + id +
                                " is running: cancel it first (POST .../cancel), then delete it");
  case Kind::runs_not_final:
    return problem_response(req, http::status::conflict,
                            "study " + id +
                                " is cancelled but a run of it is still stopping: delete it "
                                "once its runs have ended (a second or so)");
  case Kind::invalid:
    return problem_response(req, http::status::unprocessable_entity, "the change is invalid",
                            {*r.error});
  }
  return problem_response(req, http::status::internal_server_error, "unreachable");
}

// The study as GET /studies/{id} shows it, after a change.
Response study_now(ServerContext& ctx, const Request& req, const std::string& id) {
  auto view = ctx.studies.view(id);
  if (!view) return problem_response(req, http::status::not_found, "no study with id " + id);
  return json_response(req, http::status::ok, study_to_json(*view));
}

std::optional<Response> refuse_query(const RequestContext& rc) {
  if (rc.query.empty()) return std::nullopt;
  return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                          {{"/query/" + rc.query.begin()->first, "unknown query parameter"}});
}

Response patch_study(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no study with id " + id);
  if (auto bad = refuse_query(rc)) return std::move(*bad);
  auto parsed = api::parse_bounded_json(rc.request.body());
  if (parsed.status == api::JsonParse::Status::syntax)
    return problem_response(rc.request, http::status::bad_request, "the body is not valid JSON",
                            {parsed.error});
  if (!parsed.ok())
    return problem_response(rc.request, http::status::unprocessable_entity, "the change is invalid",
                            {parsed.error});
  auto change = api::parse_annotations(parsed.value);
  if (!change.ok())
    return problem_response(rc.request, http::status::unprocessable_entity, "the change is invalid",
                            change.errors);
  auto r = ctx.studies.annotate(id, rc.user, change.annotations.tags, change.annotations.note);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return study_now(ctx, rc.request, id);
}

Response archive_study(ServerContext& ctx, RequestContext& rc, bool archived) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no study with id " + id);
  if (auto bad = refuse_query(rc)) return std::move(*bad);
  auto r = ctx.studies.set_archived(id, rc.user, archived);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return study_now(ctx, rc.request, id);
}

Response delete_study(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no study with id " + id);
  if (auto bad = refuse_query(rc)) return std::move(*bad);
  auto r = ctx.studies.remove(id, rc.user);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return json_response(rc.request, http::status::ok,
                       {{"id", id},
                        {"deleted", true},
                        {"deleted_jobs", r.deleted_jobs},
                        {"results_deleted", r.results_deleted}});
}

} // namespace

void add_study_keep_routes(Router& router, ServerContext& ctx) {
  router.add_json_body(http::verb::patch, api_prefix + "/studies/{id}",
                       [&ctx](RequestContext& rc) { return patch_study(ctx, rc); });
  router.add(http::verb::delete_, api_prefix + "/studies/{id}",
             [&ctx](RequestContext& rc) { return delete_study(ctx, rc); });
  router.add(http::verb::post, api_prefix + "/studies/{id}/archive",
             [&ctx](RequestContext& rc) { return archive_study(ctx, rc, true); });
  router.add(http::verb::post, api_prefix + "/studies/{id}/restore",
             [&ctx](RequestContext& rc) { return archive_study(ctx, rc, false); });
}

} // namespace slipfront::server
