// POST /api/v1/length-fits: the experimentalist's procedure of paper Sec. 6 on one record
// (docs/length-fit.md): the body is parsed and fitted by api/length_fit/, nothing is stored.
// No token is needed (it acts for nobody and keeps nothing); the body is bounded by the
// server's --max-body-bytes, the fit's cost by the record's bounds.
#include "api/json_parse.hpp"
#include "api/length_fit/length_fit_request.hpp"
#include "server/http/api_prefix.hpp"
#include "server/http/handlers.hpp"
#include "server/http/responses.hpp"

namespace slipfront::server {

namespace {

Response invalid(const Request& req, const std::vector<api::FieldError>& errors) {
  return problem_response(req, http::status::unprocessable_entity,
                          "the record cannot be fitted (" + std::to_string(errors.size()) +
                              " error" + (errors.size() == 1 ? "" : "s") + ")",
                          errors);
}

Response fit(RequestContext& rc) {
  const Request& req = rc.request;
  const api::JsonParse body = api::parse_bounded_json(req.body());
  if (body.status == api::JsonParse::Status::syntax)
    return problem_response(req, http::status::bad_request, "the body is not valid JSON",
                            {body.error});
  if (!body.ok()) return invalid(req, {body.error});
  const api::LengthFitRequest request = api::parse_length_fit_request(body.value);
  if (!request.record) return invalid(req, request.errors);
  const api::LengthFitAnswer answer = api::answer_length_fit(*request.record, request.options);
  if (!answer.errors.empty()) return invalid(req, answer.errors);
  return json_response(req, http::status::ok, answer.body);
}

} // namespace

void add_length_fit_routes(Router& router) {
  // On the fit pool: at most --max-fits at once, never on the threads of submissions.
  router.add_json_body(
      http::verb::post, api_prefix + "/length-fits", [](RequestContext& rc) { return fit(rc); },
      Runs::fit_pool);
}

} // namespace slipfront::server
