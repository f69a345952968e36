#include "server/http/router.hpp"

#include "server/core/log.hpp"
#include "server/core/storage_error.hpp"
#include "server/http/query_string.hpp"
#include "server/http/responses.hpp"

namespace slipfront::server {

namespace {
// "GET /api/v1/jobs?..." for the log: a target of up to 16 kB is cut at 300 characters.
std::string request_line(const Request& request) {
  constexpr std::size_t shown = 300;
  std::string target(request.target().substr(0, shown));
  if (request.target().size() > shown)
    target += "... (" + std::to_string(request.target().size()) + " characters)";
  return std::string(request.method_string()) + " " + target;
}

std::vector<std::string> split_path(const std::string& path) {
  std::vector<std::string> out;
  std::size_t start = 1;
  while (start <= path.size()) {
    auto slash = path.find('/', start);
    if (slash == std::string::npos) slash = path.size();
    out.push_back(path.substr(start, slash - start));
    start = slash + 1;
  }
  return out;
}

bool match(const std::vector<std::string>& pattern, const std::vector<std::string>& path,
           std::map<std::string, std::string>& params) {
  if (pattern.size() != path.size()) return false;
  for (std::size_t i = 0; i < pattern.size(); ++i) {
    const auto& p = pattern[i];
    if (p.size() > 2 && p.front() == '{' && p.back() == '}')
      params[p.substr(1, p.size() - 2)] = path[i];
    else if (p != path[i])
      return false;
  }
  return true;
}
} // namespace

void Router::add(http::verb method, const std::string& pattern, Handler handler, Runs runs) {
  add(method, pattern, std::move(handler), [runs](const auto&) { return runs; });
}

void Router::add(http::verb method, const std::string& pattern, Handler handler, RunsFor runs_for) {
  if (method != http::verb::get) runs_for = [](const auto&) { return Runs::write_pool; };
  routes_.push_back(
      {method, pattern, split_path(pattern), std::move(handler), std::move(runs_for)});
}

Runs Router::runs(const Request& request) const {
  auto target = parse_target(request.target());
  if (!target) return Runs::io_thread;
  auto segments = split_path(target->path);
  const bool head = request.method() == http::verb::head;
  for (const auto& route : routes_) {
    std::map<std::string, std::string> params;
    if (match(route.segments, segments, params) &&
        (route.method == request.method() || (head && route.method == http::verb::get)))
      return route.runs_for(target->query);
  }
  return Runs::io_thread;
}

void Router::on_storage_unavailable(int retry_after_s,
                                    std::function<void(const std::string&)> record) {
  retry_after_s_ = retry_after_s;
  record_storage_error_ = std::move(record);
}

Response Router::dispatch(const Request& request) const {
  Response response = answer(request);
  if (request.method() == http::verb::head) response.drop_body();
  return response;
}

Response Router::answer(const Request& request) const {
  auto target = parse_target(request.target());
  if (!target)
    return problem_response(request, http::status::bad_request,
                            "malformed request target: give a path (/api/v1/...) or an absolute "
                            "http:// or https:// URL");
  auto segments = split_path(target->path);
  std::string allow;
  // HEAD is answered by the GET route, without the body (RFC 9110 §9.3.2).
  const bool head = request.method() == http::verb::head;
  for (const auto& route : routes_) {
    std::map<std::string, std::string> params;
    if (!match(route.segments, segments, params)) continue;
    if (route.method != request.method() && !(head && route.method == http::verb::get)) {
      allow += (allow.empty() ? "" : ", ") + std::string(http::to_string(route.method));
      continue;
    }
    RequestContext ctx{request, target->path, std::move(params), target->query, {}};
    try {
      return route.handler(ctx);
    } catch (const StorageError& e) {
      log_error(request_line(request) + ": " + e.what());
      if (!e.unavailable())
        return problem_response(request, http::status::internal_server_error,
                                "internal error (the server log has the details)");
      if (record_storage_error_) record_storage_error_(e.what());
      auto res = problem_response(request, http::status::service_unavailable,
                                  "the server's storage cannot take writes now (disk full or I/O "
                                  "error); retry later");
      res.set(http::field::retry_after, std::to_string(retry_after_s_));
      return res;
    } catch (const std::exception& e) {
      log_error(request_line(request) + ": " + e.what());
      // The exception's text may quote internals (SQL, library messages): it goes to the
      // log only.
      return problem_response(request, http::status::internal_server_error,
                              "internal error (the server log has the details)");
    }
  }
  if (!allow.empty()) {
    auto res = problem_response(request, http::status::method_not_allowed,
                                "method " + std::string(request.method_string()) +
                                    " is not allowed here; allowed: " + allow);
    res.set(http::field::allow, allow);
    return res;
  }
  return problem_response(request, http::status::not_found, "no such resource: " + target->path);
}

} // namespace slipfront::server
