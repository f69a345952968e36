// POST /jobs, GET /jobs, GET /jobs/{id}, POST /jobs/{id}/cancel.
#include "api/job_methods.hpp"
#include "api/json_number.hpp"
#include "server/core/job_id.hpp"
#include "server/core/priority.hpp"
#include "server/core/run_query.hpp"
#include "server/http/handlers.hpp"
#include "server/http/idempotency_key.hpp"
#include "server/http/job_filter_query.hpp"
#include "server/http/job_json.hpp"
#include "server/http/query_string.hpp"
#include "server/http/responses.hpp"
#include "server/http/run_table.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

namespace slipfront::server {

namespace {

Response not_found_job(const Request& req, const std::string& id) {
  return problem_response(req, http::status::not_found, "no job with id " + id);
}

Response submit(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& req = rc.request;
  if (ctx.draining)
    return unavailable_response(req, "the server is shutting down", ctx.retry_after_s);
  SubmitOptions options;
  options.user = rc.user;
  std::vector<api::FieldError> errors;
  if (auto it = rc.query.find("fresh"); it != rc.query.end()) {
    options.fresh = parse_bool(it->second);
    if (!options.fresh) errors.push_back({"/query/fresh", "must be true or false"});
  }
  if (auto it = rc.query.find("priority"); it != rc.query.end()) {
    const auto number = parse_long(it->second);
    options.priority = number ? priority_of(*number) : std::nullopt;
    if (!options.priority) errors.push_back({"/query/priority", priority_rule()});
  }
  options.idempotency_key = idempotency_key(req, errors);
  if (!errors.empty())
    return problem_response(req, http::status::bad_request, "invalid query parameters", errors);

  SubmitResult r = ctx.service.submit(req.body(), options);
  using Kind = SubmitResult::Kind;
  switch (r.kind) {
  case Kind::bad_json:
    return problem_response(req, http::status::bad_request, "the body is not valid JSON", r.errors);
  case Kind::invalid:
    return problem_response(req, http::status::unprocessable_entity,
                            "the job spec is invalid (" + std::to_string(r.errors.size()) +
                                " error" + (r.errors.size() == 1 ? "" : "s") + ")",
                            r.errors);
  case Kind::key_conflict:
    return problem_response(req, http::status::unprocessable_entity,
                            r.errors.empty() ? "Idempotency-Key conflict" : r.errors[0].reason);
  case Kind::queue_full:
    return unavailable_response(req,
                                "the queue is full (" +
                                    std::to_string(ctx.service.load().queue_limit) +
                                    " jobs); retry later",
                                ctx.retry_after_s);
  case Kind::created:
  case Kind::reused:
  case Kind::replayed:
    break;
  }
  auto body = job_to_json(*r.job);
  body["reused"] =
      r.kind == Kind::reused || (r.kind == Kind::replayed && !r.job->cached_from.empty());
  body["cache"] = !r.job->cached_from.empty() ? "hit" : (r.job->fresh ? "bypassed" : "miss");
  auto res = json_response(req, r.kind == Kind::replayed ? http::status::ok : http::status::created,
                           std::move(body));
  res.set(http::field::location, api_prefix + "/jobs/" + r.job->id);
  if (r.kind == Kind::replayed) res.set("Idempotent-Replayed", "true");
  return res;
}

Response get_job(ServerContext& ctx, RequestContext& rc) {
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_job(rc.request, id);
  auto job = ctx.service.get(id);
  if (!job) return not_found_job(rc.request, id);
  std::vector<std::string> fields;
  if (auto it = rc.query.find("fields"); it != rc.query.end()) fields = split_commas(it->second);
  return json_response(rc.request, http::status::ok, job_to_json(*job, fields));
}

// The cursor of the next page ("123", "o50" for a sorted listing); nullopt on the last page.
std::optional<std::string> next_cursor(const JobPage& page) {
  if (page.next_offset) return std::string("o").append(std::to_string(*page.next_offset));
  if (page.next_cursor) return std::to_string(*page.next_cursor);
  return std::nullopt;
}

// The `next` link of a listing whose page is full: the same query with the next cursor.
std::optional<std::string> next_link(const JobPage& page,
                                     const std::map<std::string, std::string>& query) {
  auto cursor = next_cursor(page);
  if (!cursor) return std::nullopt;
  std::string next = api_prefix + "/jobs?";
  for (const auto& [key, value] : query)
    if (key != "cursor") next += percent_encode(key) + "=" + percent_encode(value) + "&";
  return next + "cursor=" + *cursor;
}

// format=csv|ndjson: the run table, built one job at a time (RunTableCsv keeps each row as
// its cells' text): about 4 kB a row at the peak, not the 22 kB of a Job and a JSON row.
Response export_runs(ServerContext& ctx, RequestContext& rc, const JobFilter& filter,
                     const std::string& format) {
  RunTableCsv csv;
  std::string ndjson;
  JobPage page = ctx.service.scan(filter, [&](Job&& job, const std::string& convergence_status) {
    auto row = run_row(job, convergence_status);
    if (format == "csv")
      csv.add(row);
    else
      ndjson += row.dump() + "\n";
  });
  auto response =
      format == "csv"
          ? text_response(rc.request, http::status::ok, csv.text(), "text/csv; charset=utf-8")
          : text_response(rc.request, http::status::ok, std::move(ndjson), "application/x-ndjson");
  if (auto next = next_link(page, rc.query))
    response.set(http::field::link, "<" + *next + ">; rel=\"next\"");
  if (!page.skipped.empty())
    response.set("Skipped-Rows", std::to_string(page.skipped.size()) +
                                     " unreadable row(s) left out, the first: " +
                                     page.skipped.front().substr(0, 200));
  return response;
}

Response list_jobs(ServerContext& ctx, RequestContext& rc) {
  auto [f, fields, format, errors] = parse_job_filter(rc.query);
  if (!errors.empty())
    return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                            errors);
  if (asks_for_export(rc.query)) return export_runs(ctx, rc, f, format);
  JobPage page = ctx.service.list(f);
  nlohmann::json body;
  body["jobs"] = nlohmann::json::array();
  for (const auto& job : page.jobs)
    body["jobs"].push_back(job_to_json(job, fields));
  body["count"] = page.jobs.size();
  if (!page.skipped.empty()) body["skipped"] = page.skipped; // unreadable rows left out
  const auto cursor = next_cursor(page);
  const auto next = next_link(page, rc.query);
  body["next_cursor"] = cursor ? nlohmann::json(*cursor) : nlohmann::json(nullptr);
  body["next"] = next ? nlohmann::json(*next) : nlohmann::json(nullptr);
  return json_response(rc.request, http::status::ok, std::move(body));
}

Response cancel_job(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx.tokens, rc)) return std::move(*denied);
  const auto& id = rc.path_params.at("id");
  if (!is_valid_job_id(id)) return not_found_job(rc.request, id);
  auto r = ctx.service.cancel(id, rc.user);
  using Kind = CancelResult::Kind;
  switch (r.kind) {
  case Kind::not_found:
    return not_found_job(rc.request, id);
  case Kind::forbidden:
    return problem_response(rc.request, http::status::forbidden,
                            "job " + id + " was submitted by another user");
  case Kind::already_final:
    return problem_response(rc.request, http::status::conflict,
                            "job " + id + " has already finished (" + to_string(r.job->status) +
                                ")");
  case Kind::finishing:
    return problem_response(rc.request, http::status::conflict,
                            "job " + id +
                                " is finishing: its run has ended and its result is being "
                                "stored; it will not be cancelled");
  case Kind::cancelled: {
    auto body = job_to_json(*r.job);
    body["cancel_requested"] = true;
    return json_response(rc.request, http::status::ok, std::move(body));
  }
  case Kind::cancel_requested: {
    auto body = job_to_json(*r.job);
    body["cancel_requested"] = true;
    return json_response(rc.request, http::status::accepted, std::move(body));
  }
  }
  return problem_response(rc.request, http::status::internal_server_error, "unreachable");
}

// POST /jobs/validate: the job checked as POST /jobs would check it, nothing stored: its
// canonical spec, warnings, the source of each number with a unit and the cost estimate. An
// invalid job is a validation that succeeded with its answer, 200 {"valid": false, "errors"}
// (what POST /jobs refuses with 422; the web form asks while one types, and a browser logs
// every 4xx as an error); a body that is not JSON is 400.
Response validate_job(ServerContext& ctx, RequestContext& rc) {
  CheckResult r = ctx.service.check(rc.request.body());
  switch (r.kind) {
  case CheckResult::Kind::bad_json:
    return problem_response(rc.request, http::status::bad_request, "the body is not valid JSON",
                            r.errors);
  case CheckResult::Kind::invalid: {
    nlohmann::json errors = nlohmann::json::array();
    for (const auto& e : r.errors)
      errors.push_back({{"pointer", e.pointer}, {"reason", e.reason}});
    return json_response(rc.request, http::status::ok, {{"valid", false}, {"errors", errors}});
  }
  case CheckResult::Kind::valid:
    break;
  }
  nlohmann::json body = r.validation;
  body["valid"] = true;
  body["spec"] = r.spec->canonical;
  body["spec_sha256"] = r.spec->sha256;
  body["memory_estimate_bytes"] = api::json_bytes(r.spec->memory_estimate_bytes);
  return json_response(rc.request, http::status::ok, std::move(body));
}

// GET /job-defaults?method=NAME (fe, spectral_bi: solver/methods.hpp): the canonical spec of
// an empty job of that method (every field with its default), what the web view's submit form
// starts from.
Response job_defaults(RequestContext& rc) {
  std::string method(default_method().method.name());
  for (const auto& [key, value] : rc.query) {
    if (key != "method")
      return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                              {{"/query/" + key, "unknown query parameter (known: method)"}});
    method = value;
  }
  if (find_method(method) == nullptr)
    return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                            {{"/query/method", "must be " + api::or_list(api::method_names())}});
  auto parsed = api::parse_job(nlohmann::json{{"method", method}});
  if (!parsed.ok())
    return problem_response(rc.request, http::status::internal_server_error,
                            "the defaults do not validate", parsed.errors);
  return json_response(
      rc.request, http::status::ok,
      {{"method", method},
       {"spec", parsed.spec->canonical},
       {"memory_estimate_bytes", api::json_bytes(parsed.spec->memory_estimate_bytes)}});
}

} // namespace

void add_job_routes(Router& router, ServerContext& ctx) {
  router.add_json_body(http::verb::post, api_prefix + "/jobs",
                       [&ctx](RequestContext& rc) { return submit(ctx, rc); });
  router.add_json_body(http::verb::post, api_prefix + "/jobs/validate",
                       [&ctx](RequestContext& rc) { return validate_job(ctx, rc); });
  // An export runs on a thread of its own, at most --max-exports at once; a page of jobs
  // (at most 1000) with the other reads.
  router.add(
      http::verb::get, api_prefix + "/jobs",
      [&ctx](RequestContext& rc) { return list_jobs(ctx, rc); },
      [](const auto& query) {
        return asks_for_export(query) ? Runs::export_pool : Runs::read_pool;
      });
  router.add(http::verb::get, api_prefix + "/jobs/{id}",
             [&ctx](RequestContext& rc) { return get_job(ctx, rc); });
  router.add(http::verb::post, api_prefix + "/jobs/{id}/cancel",
             [&ctx](RequestContext& rc) { return cancel_job(ctx, rc); });
  router.add(http::verb::get, api_prefix + "/job-defaults",
             [](RequestContext& rc) { return job_defaults(rc); });
}

} // namespace slipfront::server
