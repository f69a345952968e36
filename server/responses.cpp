#include "server/responses.hpp"

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

http::response<http::string_body> json_response(const Request& req, http::status status,
                                                const nlohmann::json& body) {
  return text_response(req, status,
                       body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                       "application/json");
}

http::response<http::string_body> problem_response(const Request& req, http::status status,
                                                   const std::string& detail,
                                                   const std::vector<api::FieldError>& errors) {
  nlohmann::json body;
  body["type"] = "about:blank";
  body["title"] = std::string(http::obsolete_reason(status));
  body["status"] = static_cast<unsigned>(status);
  body["detail"] = detail;
  body["instance"] = std::string(req.target());
  if (!errors.empty()) {
    body["errors"] = nlohmann::json::array();
    for (const auto& e : errors)
      body["errors"].push_back({{"pointer", e.pointer}, {"reason", e.reason}});
  }
  return text_response(req, status,
                       body.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace),
                       "application/problem+json");
}

} // namespace slipfront::server
