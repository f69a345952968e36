#include "server/http/responses.hpp"

#include <algorithm>

#include "api/json_number.hpp"
#include "server/http/query_string.hpp"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace slipfront::server {

http::response<http::string_body> text_response(const Request& req, http::status status,
                                                std::string body, const std::string& content_type) {
  http::response<http::string_body> res{status, req.version()};
  res.set(http::field::server, "slipfront");
  res.set(http::field::content_type, content_type);
  res.set(http::field::cache_control, "no-store");
  res.keep_alive(req.keep_alive());
  res.body() = std::move(body);
  res.prepare_payload();
  return res;
}

nlohmann::json number_or_null(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

std::string fnv1a_hex(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ULL; // FNV-1a, 64 bits: offset basis and prime
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ULL;
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

namespace {
// A weak validator of a JSON body.
std::string weak_etag(const std::string& body) {
  return "W/\"" + fnv1a_hex(body) + "\"";
}
} // namespace

bool etag_list_matches(std::string_view if_none_match, std::string_view etag) {
  auto opaque = [](std::string_view tag) { return tag.substr(0, 2) == "W/" ? tag.substr(2) : tag; };
  for (std::string_view item : split_list(if_none_match))
    if (item == "*" || opaque(item) == opaque(etag)) return true;
  return false;
}

http::response<http::string_body> json_response(const Request& req, http::status status,
                                                nlohmann::json body) {
  api::whole_numbers_as_integers(body); // "n_d": 10, not 10.0 (api/json_number.hpp)
  auto res = text_response(req, status,
                           body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                           "application/json");
  // GET answers carry a weak ETag, so that pollers (the web view) send If-None-Match and get
  // 304 without a body while nothing changed.
  const bool get = req.method() == http::verb::get || req.method() == http::verb::head;
  if (get && status == http::status::ok) {
    const std::string etag = weak_etag(res.body());
    res.set(http::field::etag, etag);
    if (req.count(http::field::if_none_match) &&
        etag_list_matches(req[http::field::if_none_match], etag)) {
      res.result(http::status::not_modified);
      res.body().clear();
      res.prepare_payload();
    }
  }
  return res;
}

http::response<http::string_body> problem_response(const Request& req, http::status status,
                                                   const std::string& detail,
                                                   const std::vector<api::FieldError>& errors) {
  nlohmann::json body;
  body["type"] = "about:blank";
  body["title"] = std::string(http::obsolete_reason(status));
  body["status"] = static_cast<unsigned>(status);
  // An error body never grows with its request beyond max_listed_errors entries.
  const std::size_t listed = std::min(errors.size(), max_listed_errors);
  body["detail"] = listed == errors.size()
                       ? detail
                       : detail + "; the first " + std::to_string(listed) + " are listed, and " +
                             std::to_string(errors.size() - listed) + " more";
  body["instance"] = std::string(req.target());
  if (!errors.empty()) {
    body["errors"] = nlohmann::json::array();
    for (std::size_t i = 0; i < listed; ++i)
      body["errors"].push_back({{"pointer", errors[i].pointer}, {"reason", errors[i].reason}});
  }
  return text_response(req, status,
                       body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                       "application/problem+json");
}

} // namespace slipfront::server

namespace slipfront::server {

http::response<http::string_body>
unavailable_response(const Request& req, const std::string& detail, int retry_after_s) {
  auto res = problem_response(req, http::status::service_unavailable, detail);
  res.set(http::field::retry_after, std::to_string(retry_after_s));
  return res;
}

} // namespace slipfront::server
