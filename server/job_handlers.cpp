// POST /jobs, GET /jobs, GET /jobs/{id}, POST /jobs/{id}/cancel.
#include "server/handlers.hpp"
#include "server/job_id.hpp"
#include "server/query_string.hpp"
#include "server/responses.hpp"
#include "server/run_query.hpp"
#include "server/run_table.hpp"

#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <sstream>

namespace slipfront::server {

// The submitting user, or a 401 response when a token file is configured and the request
// carries no valid bearer token.
std::optional<Response> authenticate(ServerContext& ctx, RequestContext& rc) {
  if (!ctx.tokens) {
    rc.user = "anonymous";
    return std::nullopt;
  }
  auto header = rc.request[http::field::authorization];
  auto user = ctx.tokens->user_for_header(header);
  if (!user) {
    auto res = problem_response(rc.request, http::status::unauthorized,
                                header.empty() ? "this server needs a bearer token "
                                                 "(Authorization: Bearer <token>)"
                                               : "unknown bearer token");
    res.set(http::field::www_authenticate, "Bearer realm=\"slipfront\"");
    return Response(std::move(res));
  }
  rc.user = *user;
  return std::nullopt;
}

namespace {

const std::string prefix = "/api/v1";

std::optional<bool> parse_bool(const std::string& s) {
  if (s == "true" || s == "1" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "no") return false;
  return std::nullopt;
}

// A finite number: from_chars also reads "nan" and "inf", which no filter can mean.
std::optional<double> parse_double(const std::string& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long> parse_long(const std::string& s) {
  long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

Response not_found_job(const Request& req, const std::string& id) {
  return problem_response(req, http::status::not_found, "no job with id " + id);
}

Response submit(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx, rc)) return std::move(*denied);
  const auto& req = rc.request;
  if (ctx.draining) {
    auto res =
        problem_response(req, http::status::service_unavailable, "the server is shutting down");
    res.set(http::field::retry_after, std::to_string(ctx.retry_after_s));
    return res;
  }
  SubmitOptions options;
  options.user = rc.user;
  std::vector<api::FieldError> errors;
  if (auto it = rc.query.find("fresh"); it != rc.query.end()) {
    options.fresh = parse_bool(it->second);
    if (!options.fresh) errors.push_back({"/query/fresh", "must be true or false"});
  }
  if (auto it = rc.query.find("priority"); it != rc.query.end()) {
    auto p = parse_long(it->second);
    if (!p || *p < -100 || *p > 100)
      errors.push_back({"/query/priority", "must be an integer in [-100, 100]"});
    else
      options.priority = static_cast<int>(*p);
  }
  std::string key(req["Idempotency-Key"]);
  if (req.count("Idempotency-Key") && (key.empty() || key.size() > 200))
    errors.push_back({"/headers/Idempotency-Key", "must be 1 to 200 characters"});
  if (!errors.empty())
    return problem_response(req, http::status::bad_request, "invalid query parameters", errors);
  options.idempotency_key = key;

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
  case Kind::queue_full: {
    auto res = problem_response(req, http::status::service_unavailable,
                                "the queue is full (" + std::to_string(ctx.queue.limit()) +
                                    " jobs); retry later");
    res.set(http::field::retry_after, std::to_string(ctx.retry_after_s));
    return res;
  }
  case Kind::created:
  case Kind::reused:
  case Kind::replayed:
    break;
  }
  auto body = job_to_json(*r.job);
  body["reused"] =
      r.kind == Kind::reused || (r.kind == Kind::replayed && !r.job->cached_from.empty());
  body["cache"] = !r.job->cached_from.empty() ? "hit" : (r.job->fresh ? "bypassed" : "miss");
  auto res =
      json_response(req, r.kind == Kind::replayed ? http::status::ok : http::status::created, body);
  res.set(http::field::location, prefix + "/jobs/" + r.job->id);
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

Response list_jobs(ServerContext& ctx, RequestContext& rc) {
  JobFilter f;
  std::vector<api::FieldError> errors;
  const auto& q = rc.query;
  static const std::set<std::string> known = {
      "status", "tag",        "name",     "outcome", "submitted_by", "spec_sha256",
      "L_min",  "L_max",      "n_d_min",  "n_d_max", "limit",        "cursor",
      "fields", "scene_hash", "study_id", "where",   "sort",         "format"};
  for (const auto& [key, value] : q)
    if (!known.count(key)) errors.push_back({"/query/" + key, "unknown query parameter"});
  if (auto it = q.find("status"); it != q.end())
    for (const auto& s : split_commas(it->second)) {
      auto st = parse_status(s);
      if (st)
        f.statuses.push_back(*st);
      else
        errors.push_back({"/query/status", "unknown status " + s});
    }
  auto text = [&](const char* key, std::string& out) {
    if (auto it = q.find(key); it != q.end()) out = it->second;
  };
  text("tag", f.tag);
  text("name", f.name);
  text("outcome", f.outcome);
  text("submitted_by", f.submitted_by);
  text("spec_sha256", f.spec_sha256);
  text("scene_hash", f.scene_hash);
  text("study_id", f.study_id);
  auto number = [&](const char* key, std::optional<double>& out) {
    if (auto it = q.find(key); it != q.end()) {
      out = parse_double(it->second);
      if (!out) errors.push_back({std::string("/query/") + key, "must be a finite number"});
    }
  };
  number("L_min", f.L_min);
  number("L_max", f.L_max);
  number("n_d_min", f.n_d_min);
  number("n_d_max", f.n_d_max);
  std::string format = "json";
  if (auto it = q.find("format"); it != q.end()) {
    format = it->second;
    if (format != "json" && format != "csv" && format != "ndjson")
      errors.push_back({"/query/format", "must be json, csv or ndjson, got '" + format + "'"});
  }
  const bool table = format == "csv" || format == "ndjson";
  const long max_limit = table ? 100000 : 1000;
  if (table) f.limit = 10000;
  if (auto it = q.find("limit"); it != q.end()) {
    auto l = parse_long(it->second);
    if (!l || *l < 1 || *l > max_limit)
      errors.push_back({"/query/limit", "must be an integer in [1, " + std::to_string(max_limit) +
                                            "] for format=" + format});
    else
      f.limit = static_cast<int>(*l);
  }
  try {
    if (auto it = q.find("where"); it != q.end()) f.conditions = parse_where(it->second);
  } catch (const QueryError& e) {
    errors.push_back({"/query/" + e.parameter(), e.what()});
  }
  try {
    if (auto it = q.find("sort"); it != q.end()) f.sort = parse_sort(it->second);
  } catch (const QueryError& e) {
    errors.push_back({"/query/" + e.parameter(), e.what()});
  }
  if (auto it = q.find("cursor"); it != q.end()) {
    // Newest-first listings page by seq ("123"), sorted ones by offset ("o50").
    const std::string& text = it->second;
    bool sorted = !f.sort.empty();
    auto c = parse_long(sorted && !text.empty() && text[0] == 'o' ? text.substr(1) : text);
    if (!c || *c < 0 || (sorted && text[0] != 'o') || (!sorted && text[0] == 'o'))
      errors.push_back({"/query/cursor", "must be a cursor returned as next_cursor by a listing "
                                         "with the same sort"});
    else if (sorted)
      f.offset = *c;
    else
      f.before_seq = *c;
  }
  std::vector<std::string> fields;
  if (auto it = q.find("fields"); it != q.end()) fields = split_commas(it->second);
  if (!errors.empty())
    return problem_response(rc.request, http::status::bad_request, "invalid query parameters",
                            errors);
  JobPage page = ctx.service.list(f);
  std::optional<std::string> next_cursor;
  if (page.next_cursor) next_cursor = std::to_string(*page.next_cursor);
  if (page.next_offset) next_cursor = "o" + std::to_string(*page.next_offset);
  std::optional<std::string> next;
  if (next_cursor) {
    next = prefix + "/jobs?";
    for (const auto& [key, value] : q)
      if (key != "cursor") *next += percent_encode(key) + "=" + percent_encode(value) + "&";
    *next += "cursor=" + *next_cursor;
  }
  if (table) {
    std::vector<nlohmann::ordered_json> rows;
    for (const auto& job : page.jobs) {
      auto it = page.convergence_status.find(job.id);
      rows.push_back(run_row(job, it == page.convergence_status.end() ? "" : it->second));
    }
    auto response = format == "csv" ? text_response(rc.request, http::status::ok, runs_csv(rows),
                                                    "text/csv; charset=utf-8")
                                    : text_response(rc.request, http::status::ok, runs_ndjson(rows),
                                                    "application/x-ndjson");
    if (next) response.set(http::field::link, "<" + *next + ">; rel=\"next\"");
    return response;
  }
  nlohmann::json body;
  body["jobs"] = nlohmann::json::array();
  for (const auto& job : page.jobs)
    body["jobs"].push_back(job_to_json(job, fields));
  body["count"] = page.jobs.size();
  if (next_cursor) {
    body["next_cursor"] = *next_cursor;
    body["next"] = *next;
  } else {
    body["next_cursor"] = nullptr;
    body["next"] = nullptr;
  }
  return json_response(rc.request, http::status::ok, body);
}

Response cancel_job(ServerContext& ctx, RequestContext& rc) {
  if (auto denied = authenticate(ctx, rc)) return std::move(*denied);
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
  case Kind::cancelled: {
    auto body = job_to_json(*r.job);
    body["cancel_requested"] = true;
    return json_response(rc.request, http::status::ok, body);
  }
  case Kind::cancel_requested: {
    auto body = job_to_json(*r.job);
    body["cancel_requested"] = true;
    return json_response(rc.request, http::status::accepted, body);
  }
  }
  return problem_response(rc.request, http::status::internal_server_error, "unreachable");
}

} // namespace

void add_job_routes(Router& router, ServerContext& ctx) {
  router.add(http::verb::post, prefix + "/jobs",
             [&ctx](RequestContext& rc) { return submit(ctx, rc); });
  router.add(
      http::verb::get, prefix + "/jobs", [&ctx](RequestContext& rc) { return list_jobs(ctx, rc); },
      true);
  router.add(http::verb::get, prefix + "/jobs/{id}",
             [&ctx](RequestContext& rc) { return get_job(ctx, rc); });
  router.add(http::verb::post, prefix + "/jobs/{id}/cancel",
             [&ctx](RequestContext& rc) { return cancel_job(ctx, rc); });
}

} // namespace slipfront::server
