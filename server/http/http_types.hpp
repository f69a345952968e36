// The Beast types the HTTP layer shares.
#pragma once

#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>

#include <cstdint>
#include <map>
#include <string>
#include <type_traits>

namespace slipfront::server {

namespace beast = boost::beast;
namespace http = boost::beast::http;

using Request = http::request<http::string_body>;

// A response of any body type, with its status code kept for the request statistics.
class Response {
public:
  template <class Body, class Fields>
  Response(http::response<Body, Fields>&& res) // NOLINT: implicit on purpose
      : status_(res.result_int()), header_(res.base()), held_bytes_(held_by(res)),
        message_(std::move(res)) {}
  unsigned status() const { return status_; }
  // The bytes of body this answer holds in memory until it is sent (a file body: none).
  std::uint64_t held_bytes() const { return held_bytes_; }
  bool keep_alive() const { return message_.keep_alive(); }
  http::message_generator take() { return std::move(message_); }
  // The answer to HEAD: the same header (Content-Length included), no body.
  void drop_body() {
    http::response<http::empty_body> head(header_);
    message_ = http::message_generator(std::move(head));
    held_bytes_ = 0;
  }

private:
  template <class Body, class Fields>
  static std::uint64_t held_by(const http::response<Body, Fields>& res) {
    if constexpr (std::is_same_v<Body, http::string_body>)
      return res.body().size();
    else
      return 0;
  }

  unsigned status_;
  http::response_header<> header_;
  std::uint64_t held_bytes_ = 0;
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
