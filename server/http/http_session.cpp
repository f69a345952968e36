#include "server/http/http_session.hpp"

#include "server/core/log.hpp"
#include "server/http/api_prefix.hpp"
#include "server/http/responses.hpp"

#include <boost/asio/dispatch.hpp>
#include <boost/asio/post.hpp>

#include <algorithm>

namespace slipfront::server {

namespace net = boost::asio;

HttpSession::HttpSession(net::ip::tcp::socket&& socket, const Router& router, ServerStats& stats,
                         SessionLimits limits, std::shared_ptr<std::atomic<int>> open_count)
    : stream_(std::move(socket)), read_deadline_(stream_.get_executor()), router_(router),
      stats_(stats), limits_(limits), open_count_(std::move(open_count)) {
  if (open_count_) ++*open_count_;
}

HttpSession::~HttpSession() {
  if (open_count_) --*open_count_;
}

void HttpSession::run() {
  net::dispatch(stream_.get_executor(),
                beast::bind_front_handler(&HttpSession::read_header, shared_from_this()));
}

void HttpSession::read_header() {
  parser_.emplace();
  // The parser checks a Content-Length against its limit with the header, before the path is
  // known: the larger of the two limits here, the request's own in on_header().
  body_limit_ = std::max(limits_.max_body_bytes, limits_.max_import_bytes);
  parser_->body_limit(body_limit_);
  parser_->header_limit(16 * 1024);
  arm_read_deadline();
  http::async_read_header(stream_, buffer_, *parser_,
                          beast::bind_front_handler(&HttpSession::on_header, shared_from_this()));
}

void HttpSession::arm_read_deadline() {
  stream_.expires_never();
  timed_out_ = false;
  read_deadline_.expires_after(limits_.request_timeout);
  read_deadline_.async_wait([weak = weak_from_this()](beast::error_code ec) {
    if (ec) return; // cancelled: the request arrived in time
    if (auto self = weak.lock()) {
      self->timed_out_ = true;
      beast::error_code ignored;
      self->stream_.socket().cancel(ignored);
    }
  });
}

void HttpSession::on_header(beast::error_code ec, std::size_t) {
  started_ = std::chrono::steady_clock::now();
  if (ec == net::error::operation_aborted && timed_out_) ec = beast::error::timeout;
  if (ec == http::error::end_of_stream || ec == net::error::connection_reset ||
      ec == net::error::eof)
    return close();
  if (ec == beast::error::timeout) {
    // An idle keep-alive connection just closes; a half-sent request gets a 408.
    if (parser_->got_some() || buffer_.size() > 0)
      return reject(http::status::request_timeout, "the request was not received in time");
    return close();
  }
  if (ec == http::error::body_limit)
    return reject(http::status::payload_too_large,
                  "the body is larger than the limit of " + std::to_string(body_limit_) + " bytes");
  if (ec == http::error::header_limit)
    return reject(http::status::request_header_fields_too_large, "the headers are too large");
  if (ec) return reject(http::status::bad_request, "malformed request: " + ec.message());
  if (parser_->is_done()) return on_body({}, 0); // no body

  auto& req = parser_->get();
  // A run archive (POST /imports) may be larger than a JSON body.
  const std::string_view target(req.target().data(), req.target().size());
  const bool import = req.method() == http::verb::post &&
                      target.substr(0, target.find('?')) == api_prefix + "/imports";
  body_limit_ = import ? limits_.max_import_bytes : limits_.max_body_bytes;
  if (const auto length = parser_->content_length(); length && *length > body_limit_)
    return reject(http::status::payload_too_large,
                  "the body is larger than the limit of " + std::to_string(body_limit_) + " bytes");
  parser_->body_limit(body_limit_); // a chunked body is counted against it as it arrives
  if (beast::iequals(req[http::field::expect], "100-continue")) {
    // curl waits for this before sending larger bodies.
    auto cont = std::make_shared<http::response<http::empty_body>>(http::status::continue_, 11);
    http::async_write(stream_, *cont,
                      [self = shared_from_this(), cont](beast::error_code wec, std::size_t) {
                        if (wec) return self->close();
                        self->stream_.expires_never();
                        self->read_body();
                      });
    return;
  }
  read_body();
}

void HttpSession::read_body() {
  http::async_read(stream_, buffer_, *parser_,
                   beast::bind_front_handler(&HttpSession::on_body, shared_from_this()));
}

void HttpSession::on_body(beast::error_code ec, std::size_t) {
  read_deadline_.cancel();
  if (ec == net::error::operation_aborted && timed_out_) ec = beast::error::timeout;
  if (ec == beast::error::timeout)
    return reject(http::status::request_timeout, "the request body was not received in time");
  if (ec == http::error::body_limit)
    return reject(http::status::payload_too_large,
                  "the body is larger than the limit of " + std::to_string(body_limit_) + " bytes");
  if (ec == http::error::end_of_stream || ec == net::error::connection_reset ||
      ec == net::error::eof)
    return close();
  if (ec) return reject(http::status::bad_request, "malformed request: " + ec.message());
  Request req = parser_->release();
  const auto& pools = limits_.pools;
  const Runs runs = router_.runs(req);
  boost::asio::thread_pool* pool = runs == Runs::read_pool    ? pools.reads
                                   : runs == Runs::write_pool ? pools.writes
                                                              : nullptr;
  if (pool) {
    net::post(*pool, handler_task(std::move(req)));
    return;
  }
  // Every thread of a bounded pool taken: come back in a second rather than wait here.
  BoundedPool* bounded = runs == Runs::export_pool ? pools.exports
                         : runs == Runs::fit_pool  ? pools.fits
                                                   : nullptr;
  if (bounded) {
    // The answer is handed back once its task no longer counts against the bound: a client
    // that asks again as soon as it is answered finds the place free.
    auto answer = std::make_shared<std::optional<Response>>();
    auto self = shared_from_this();
    const bool taken =
        bounded->try_post([self, req, answer] { answer->emplace(self->router_.dispatch(req)); },
                          [self, answer] {
                            net::post(self->stream_.get_executor(),
                                      [self, answer] { self->send(std::move(**answer), false); });
                          });
    if (!taken) send(unavailable_response(req, bounded->busy_reason() + "; retry later", 1), false);
    return;
  }
  Response response = router_.dispatch(req);
  send(std::move(response), false);
}

std::function<void()> HttpSession::handler_task(Request req) {
  // A handler that may block: the I/O thread goes back to other connections meanwhile.
  return [self = shared_from_this(), req = std::move(req)] {
    auto response = std::make_shared<Response>(self->router_.dispatch(req));
    net::post(self->stream_.get_executor(),
              [self, response] { self->send(std::move(*response), false); });
  };
}

void HttpSession::send(Response response, bool close_after) {
  read_deadline_.cancel();
  if (limits_.unsent && response.held_bytes() > 0) {
    auto reserved = ByteReservation::take(limits_.unsent, response.held_bytes());
    if (!reserved) {
      Request req;
      req.version(11);
      auto busy =
          unavailable_response(req,
                               "the server holds " + std::to_string(limits_.unsent->limit() >> 20) +
                                   " MiB of answers its clients have not read yet; retry later",
                               5);
      busy.keep_alive(response.keep_alive());
      response = Response(std::move(busy));
      reserved = ByteReservation::take(limits_.unsent, response.held_bytes()); // small: allowed
    }
    unsent_ = std::move(*reserved);
  }
  stats_.record_request(
      response.status(),
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count());
  const bool keep_alive = response.keep_alive() && !close_after;
  writing_.emplace(response.take());
  write_deadline_ = std::chrono::steady_clock::now() + limits_.write_timeout;
  write_some(keep_alive);
}

void HttpSession::write_some(bool keep_alive) {
  beast::error_code ec;
  const auto buffers = writing_->prepare(ec);
  if (ec) return on_write(keep_alive, ec);
  // The stream's expiry closes the socket: a client that reads nothing is cut after
  // send_timeout, a slow one that keeps reading after write_timeout.
  const auto left = write_deadline_ - std::chrono::steady_clock::now();
  stream_.expires_after(std::min<std::chrono::steady_clock::duration>(limits_.send_timeout, left));
  stream_.async_write_some(
      buffers, [self = shared_from_this(), keep_alive](beast::error_code wec, std::size_t n) {
        if (wec) return self->on_write(keep_alive, wec);
        self->writing_->consume(n);
        if (self->writing_->is_done()) return self->on_write(keep_alive, {});
        self->write_some(keep_alive);
      });
}

void HttpSession::on_write(bool keep_alive, beast::error_code ec) {
  writing_.reset(); // the body goes now: a file it streamed from is closed
  unsent_.reset();
  stream_.expires_never();
  if (ec) return close();
  if (!keep_alive) return drain_then_close();
  read_header();
}

void HttpSession::reject(http::status status, const std::string& detail) {
  Request req;
  req.version(11);
  req.target(parser_ && parser_->is_header_done() ? parser_->get().target() : "");
  req.keep_alive(false);
  auto res = problem_response(req, status, detail);
  res.keep_alive(false);
  send(Response(std::move(res)), true);
}

// After a response with "Connection: close" the client may still be sending (a body over
// the limit): closing at once would reset the connection and lose the response. Shut down
// our side, then read and discard what comes, for a bounded time and size.
void HttpSession::drain_then_close() {
  beast::error_code ec;
  stream_.socket().shutdown(net::ip::tcp::socket::shutdown_send, ec);
  stream_.expires_after(std::chrono::seconds(5));
  stream_.async_read_some(net::buffer(discard_),
                          [self = shared_from_this()](beast::error_code rec, std::size_t n) {
                            self->discarded_ += n;
                            if (rec || self->discarded_ > (64u << 20)) return self->close();
                            self->drain_then_close();
                          });
}

void HttpSession::close() {
  read_deadline_.cancel();
  beast::error_code ec;
  stream_.socket().shutdown(net::ip::tcp::socket::shutdown_both, ec);
  stream_.socket().close(ec);
}

} // namespace slipfront::server
