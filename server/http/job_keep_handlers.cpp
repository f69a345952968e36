// What an owner does with a run after submission (docs/server.md "Keep, annotate, share"):
// PATCH /jobs/{id} (tags replaced, added or removed; note), POST /jobs/{id}/archive and /restore,
// DELETE /jobs/{id}. With a token file, only the user who submitted the run may change it (as for
// cancel).
#include "api/json_parse.hpp"
#include "api/run_annotations.hpp"
#include "server/core/job_id.hpp"
#include "server/http/handlers.hpp"
#include "server/http/job_json.hpp"
#include "server/http/responses.hpp"

namespace slipfront::server {

namespace {

// The refusals every change shares; nullopt when it was done.
std::optional<Response> refusal(const Request& req, const std::string& id, const KeepResult& r) {
  using Kind = KeepResult::Kind;
  switch (r.kind) {
  case Kind::done:
    return std::nullopt;
  case Kind::not_found:
    return problem_response(req, http::status::not_found, "no job with id " + id);
  case Kind::forbidden:
    return problem_response(req, http::status::forbidden,
                            "job " + id +
                                " was submitted by another user: only its owner may "
                                "change it");
  case Kind::not_final:
    return problem_response(req, http::status::conflict,
                            "job " + id + " is " + to_string(r.job->status) +
                                ": cancel it first (POST .../cancel), then delete it");
  case Kind::in_study:
    return problem_response(req, http::status::conflict,
                            "job " + id + " is a run of study " + r.study_id +
                                ", which keeps its runs: archive it instead (POST .../archive)");
  case Kind::invalid:
    return problem_response(req, http::status::unprocessable_entity, "the change is invalid",
                            {*r.error});
  }
  return problem_response(req, http::status::internal_server_error, "unreachable");
}

Response patch_job(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no job with id " + id);
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
  auto r = ctx.service.annotate(id, rc.user, change.annotations.tags, change.annotations.note);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return json_response(rc.request, http::status::ok, job_to_json(*r.job));
}

Response archive_job(ServerContext& ctx, RequestContext& rc, bool archived) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no job with id " + id);
  auto r = ctx.service.set_archived(id, rc.user, archived);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return json_response(rc.request, http::status::ok, job_to_json(*r.job));
}

Response delete_job(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id))
    return problem_response(rc.request, http::status::not_found, "no job with id " + id);
  auto r = ctx.service.remove(id, rc.user);
  if (auto refused = refusal(rc.request, id, r)) return std::move(*refused);
  return json_response(rc.request, http::status::ok,
                       {{"id", id}, {"deleted", true}, {"result_deleted", r.result_deleted}});
}

} // namespace

void add_job_keep_routes(Router& router, ServerContext& ctx) {
  router.add_json_body(http::verb::patch, api_prefix + "/jobs/{id}",
                       [&ctx](RequestContext& rc) { return patch_job(ctx, rc); });
  router.add(http::verb::delete_, api_prefix + "/jobs/{id}",
             [&ctx](RequestContext& rc) { return delete_job(ctx, rc); });
  router.add(http::verb::post, api_prefix + "/jobs/{id}/archive",
             [&ctx](RequestContext& rc) { return archive_job(ctx, rc, true); });
  router.add(http::verb::post, api_prefix + "/jobs/{id}/restore",
             [&ctx](RequestContext& rc) { return archive_job(ctx, rc, false); });
}

} // namespace slipfront::server
