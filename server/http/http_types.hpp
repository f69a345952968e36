// The Beast types the HTTP layer shares.
#pragma once

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <map>
#include <string>

namespace slipfront::server {

namespace beast = boost::beast;
namespace http = boost::beast::http;

using Request = http::request<http::string_body>;

// A response of any body type, with its status code kept for the request statistics.
class Response {
public:
  template <class Body, class Fields>
  Response(http::response<Body, Fields>&& res) // NOLINT: implicit on purpose
      : status_(res.result_int()), header_(res.base()), message_(std::move(res)) {}
  unsigned status() const { return status_; }
  bool keep_alive() const { return message_.keep_alive(); }
  http::message_generator take() { return std::move(message_); }
  // The answer to HEAD: the same header (Content-Length included), no body.
  void drop_body() {
    http::response<http::empty_body> head(header_);
    message_ = http::message_generator(std::move(head));
  }

private:
  unsigned status_;
  http::response_header<> header_;
  http::message_generator message_;
};

// A request as a handler sees it: the path split from its query, the {placeholders} of
// the route and the decoded query parameters.
struct RequestContext {
  const Request& request;
  std::string path;
  std::map<std::string, std::string> path_params;
  std::map<std::string, std::string> query;
  std::string user; // authenticated user ("" if none)
};

} // namespace slipfront::server
