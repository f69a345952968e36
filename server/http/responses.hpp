// Building responses: JSON, plain text, and errors as application/problem+json (RFC 9457)
// naming each bad field by its JSON pointer.
#pragma once

#include "api/job_spec.hpp"
#include "server/http/http_types.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

http::response<http::string_body> json_response(const Request& req, http::status status,
                                                nlohmann::json body);
http::response<http::string_body> text_response(const Request& req, http::status status,
                                                std::string body, const std::string& content_type);
// A number, or null for NaN and infinities (which JSON cannot hold).
nlohmann::json number_or_null(double v);
// The 64-bit FNV-1a hash of `bytes` as 16 hex digits (the server's entity tags).
std::string fnv1a_hex(const std::string& bytes);

// Whether an If-None-Match header value matches `etag`: "*", or a list of entity tags one of
// which equals it under the weak comparison of RFC 9110 §8.8.3.2 (W/ prefixes ignored on both
// sides).
bool etag_list_matches(std::string_view if_none_match, std::string_view etag);
// At most this many field errors are listed in a problem body; the detail says how many more
// there were.
inline constexpr std::size_t max_listed_errors = 100;
// errors: [{"pointer": ..., "reason": ...}] (the first max_listed_errors)
http::response<http::string_body> problem_response(const Request& req, http::status status,
                                                   const std::string& detail,
                                                   const std::vector<api::FieldError>& errors = {});
// 503 with Retry-After: the server cannot take this now (a bound is reached, the disk is
// short, it is shutting down); the same request may pass later.
http::response<http::string_body>
unavailable_response(const Request& req, const std::string& detail, int retry_after_s);

} // namespace slipfront::server
