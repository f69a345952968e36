// One HTTP/1.1 connection: read a request (headers first, answering Expect: 100-continue,
// then the body up to the size limit), route it, write the response, repeat while the
// client keeps the connection alive. Every read has a deadline; malformed, oversized or
// slow requests get a 4xx and the connection is closed.
#pragma once

#include "server/core/server_stats.hpp"
#include "server/http/router.hpp"
#include "server/http/work_pools.hpp"

#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>

namespace slipfront::server {

// The bytes of answers built in memory and not yet taken by their clients, over all
// connections: a client that asks and never reads holds its answer until the write timeout,
// so their sum is bounded (docs/reliability.md). An answer of at most `always_allowed` bytes
// is never refused (errors, status, health).
class UnsentBytes {
public:
  static constexpr std::uint64_t always_allowed = 64 * 1024;
  explicit UnsentBytes(std::uint64_t limit) : limit_(limit) {}
  // Counts `n` in, unless that would pass the limit (then false, nothing counted).
  bool reserve(std::uint64_t n);
  void release(std::uint64_t n) { held_ -= n; }
  std::uint64_t held() const { return held_; }
  std::uint64_t limit() const { return limit_; }

private:
  std::uint64_t limit_;
  std::atomic<std::uint64_t> held_{0};
};

struct SessionLimits {
  std::uint64_t max_body_bytes = 1 << 20;
  std::uint64_t max_import_bytes = std::uint64_t{1} << 30; // POST <api>/imports (run archives)
  std::chrono::seconds request_timeout{30}; // to receive a whole request (and idle keep-alive)
  std::chrono::seconds write_timeout{600};  // to send a whole response (large result files)
  int max_connections = 256; // open at once; more are answered 503 and closed at once
  // Shared by every session; null = no bound.
  std::shared_ptr<UnsentBytes> unsent;
  // Where the routes that may block run (Router::runs); a null pool = on the I/O thread.
  WorkPools pools;
};

class HttpSession : public std::enable_shared_from_this<HttpSession> {
public:
  // `open_count` (may be null) counts the sessions alive: +1 here, -1 when destroyed.
  HttpSession(boost::asio::ip::tcp::socket&& socket, const Router& router, ServerStats& stats,
              SessionLimits limits, std::shared_ptr<std::atomic<int>> open_count = nullptr);
  ~HttpSession();
  HttpSession(const HttpSession&) = delete;
  HttpSession& operator=(const HttpSession&) = delete;
  void run();

private:
  void read_header();
  void on_header(beast::error_code ec, std::size_t bytes);
  void read_body();
  void on_body(beast::error_code ec, std::size_t bytes);
  // Dispatches `req` on a thread of a pool; the answer is sent from the session's strand.
  std::function<void()> handler_task(Request req);
  void send(Response response, bool close_after);
  void on_write(bool keep_alive, beast::error_code ec, std::size_t bytes);
  void reject(http::status status, const std::string& detail); // 4xx, then close
  void drain_then_close();
  void close();
  void arm_read_deadline();
  void release_unsent(); // the answer being written no longer counts in limits_.unsent

  beast::tcp_stream stream_;
  // The read deadline is a timer that cancels the read (not tcp_stream's expiry, which
  // closes the socket): a slow client still gets its 408.
  boost::asio::steady_timer read_deadline_;
  bool timed_out_ = false;
  beast::flat_buffer buffer_;
  std::optional<http::request_parser<http::string_body>> parser_;
  const Router& router_;
  ServerStats& stats_;
  SessionLimits limits_;
  std::uint64_t body_limit_ = 0; // of the request being read
  std::chrono::steady_clock::time_point started_;
  std::array<char, 8192> discard_{};
  std::size_t discarded_ = 0;
  std::shared_ptr<std::atomic<int>> open_count_;
  std::uint64_t unsent_held_ = 0; // counted in limits_.unsent for the answer being written
};

} // namespace slipfront::server
