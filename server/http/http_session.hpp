// One HTTP/1.1 connection: read a request (headers first, answering Expect: 100-continue,
// then the body up to the size limit), route it, write the response, repeat while the
// client keeps the connection alive. Every read has a deadline; malformed, oversized or
// slow requests get a 4xx and the connection is closed.
#pragma once

#include "server/core/byte_budget.hpp"
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

struct SessionLimits {
  std::uint64_t max_body_bytes = 1 << 20;
  std::uint64_t max_import_bytes = std::uint64_t{1} << 30; // POST <api>/imports (run archives)
  std::chrono::seconds request_timeout{30}; // to receive a whole request (and idle keep-alive)
  std::chrono::seconds write_timeout{600};  // to send a whole response (large result files)
  // A client that takes no byte of an answer for this long is cut (its answer, and the file
  // an answer streams from, released): the write timeout alone let an unread export pin
  // its file for ten minutes.
  std::chrono::seconds send_timeout{30};
  int max_connections = 256; // open at once; more are answered 503 and closed at once
  // The bytes of answers built in memory and not yet taken by their clients, over all
  // connections (docs/reliability.md): shared by every session; null = no bound. Result
  // files and exports stream from disk and do not count here.
  std::shared_ptr<ByteBudget> unsent;
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
  // Writes the answer a chunk at a time, each within send_timeout (and all of it within
  // write_timeout of its start).
  void write_some(bool keep_alive);
  void on_write(bool keep_alive, beast::error_code ec);
  void reject(http::status status, const std::string& detail); // 4xx, then close
  void drain_then_close();
  void close();
  void arm_read_deadline();

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
  // The answer being written, and its bytes counted in limits_.unsent.
  std::optional<http::message_generator> writing_;
  ByteReservation unsent_;
  std::chrono::steady_clock::time_point write_deadline_;
};

} // namespace slipfront::server
