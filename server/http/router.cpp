#include "server/http/router.hpp"

#include "server/core/log.hpp"
#include "server/core/storage_error.hpp"
#include "server/http/query_string.hpp"
#include "server/http/responses.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string_view>

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

// The media type of a Content-Type value, lower case, without parameters:
// "Application/JSON; charset=utf-8" -> "application/json".
std::string media_type(std::string_view content_type) {
  std::string type(content_type.substr(0, content_type.find(';')));
  type.erase(0, type.find_first_not_of(" \t"));
  type.erase(type.find_last_not_of(" \t") + 1);
  for (char& c : type)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return type;
}

// 415 for a body the route cannot read: the only media type it takes is application/json
// (RFC 9110 §15.5.16: Accept names it).
std::optional<Response> refuse_media_type(const Request& request) {
  const auto field = request.find(http::field::content_type);
  if (field == request.end() || media_type(field->value()) == "application/json")
    return std::nullopt;
  auto res = problem_response(request, http::status::unsupported_media_type,
                              "Content-Type \"" + std::string(field->value()) +
                                  "\" is not accepted here: send the body as application/json");
  res.set(http::field::accept, "application/json");
  return Response(std::move(res));
}

// "GET, HEAD, POST": the methods of the routes of one path, HEAD wherever GET is.
std::string allow_header(std::vector<std::string> methods) {
  if (std::find(methods.begin(), methods.end(), "GET") != methods.end()) methods.push_back("HEAD");
  std::sort(methods.begin(), methods.end());
  methods.erase(std::unique(methods.begin(), methods.end()), methods.end());
  std::string allow;
  for (const std::string& method : methods)
    allow += (allow.empty() ? "" : ", ") + method;
  return allow;
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
  // Other methods write, except on a bounded pool of their own.
  if (method != http::verb::get)
    runs_for = [inner = std::move(runs_for)](const auto& query) {
      const Runs runs = inner(query);
      return runs == Runs::export_pool || runs == Runs::fit_pool ? runs : Runs::write_pool;
    };
  routes_.push_back(
      {method, pattern, split_path(pattern), std::move(handler), std::move(runs_for)});
}

void Router::add_json_body(http::verb method, const std::string& pattern, Handler handler,
                           Runs runs) {
  add(method, pattern, std::move(handler), runs);
  routes_.back().json_body = true;
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
  std::vector<std::string> allowed; // the methods of the path, for a 405
  // HEAD is answered by the GET route, without the body (RFC 9110 §9.3.2).
  const bool head = request.method() == http::verb::head;
  for (const auto& route : routes_) {
    std::map<std::string, std::string> params;
    if (!match(route.segments, segments, params)) continue;
    if (route.method != request.method() && !(head && route.method == http::verb::get)) {
      allowed.emplace_back(http::to_string(route.method));
      continue;
    }
    if (route.json_body)
      if (auto refusal = refuse_media_type(request)) return std::move(*refusal);
    RequestContext ctx{request, target->path, std::move(params), target->query, {}};
    try {
      return route.handler(ctx);
    } catch (const StorageError& e) {
      log_error(request_line(request) + ": " + e.what());
      if (!e.unavailable())
        return problem_response(request, http::status::internal_server_error,
                                "internal error (the server log has the details)");
      if (record_storage_error_) record_storage_error_(e.what());
      return unavailable_response(request,
                                  "the server's storage cannot take writes now (disk full or I/O "
                                  "error); retry later",
                                  retry_after_s_);
    } catch (const std::exception& e) {
      log_error(request_line(request) + ": " + e.what());
      // The exception's text may quote internals (SQL, library messages): it goes to the
      // log only.
      return problem_response(request, http::status::internal_server_error,
                              "internal error (the server log has the details)");
    }
  }
  if (!allowed.empty()) {
    const std::string allow = allow_header(std::move(allowed));
    auto res = problem_response(request, http::status::method_not_allowed,
                                "method " + std::string(request.method_string()) +
                                    " is not allowed here; allowed: " + allow);
    res.set(http::field::allow, allow);
    return res;
  }
  return problem_response(request, http::status::not_found, "no such resource: " + target->path);
}

} // namespace slipfront::server
