// Accepts connections and starts an HttpSession on its own strand for each.
#pragma once

#include "server/http/http_session.hpp"

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include <atomic>
#include <chrono>

#include <memory>

namespace slipfront::server {

class Listener : public std::enable_shared_from_this<Listener> {
public:
  // Binds and listens at once (throws with the address on failure).
  Listener(boost::asio::io_context& ioc, const boost::asio::ip::tcp::endpoint& endpoint,
           const Router& router, ServerStats& stats, SessionLimits limits);
  void run();
  void stop(); // stop accepting; open connections finish their current request
  boost::asio::ip::tcp::endpoint local_endpoint() const { return acceptor_.local_endpoint(); }

  int open_connections() const { return *open_; }

private:
  void accept();
  void on_accept(beast::error_code ec, boost::asio::ip::tcp::socket socket);
  // Out of file descriptors (EMFILE...): accepting again at once would spin; wait a little.
  void accept_later(std::chrono::milliseconds delay);

  boost::asio::io_context& ioc_;
  boost::asio::ip::tcp::acceptor acceptor_;
  const Router& router_;
  ServerStats& stats_;
  SessionLimits limits_;
  std::shared_ptr<std::atomic<int>> open_ = std::make_shared<std::atomic<int>>(0);
  boost::asio::steady_timer retry_timer_;
};

} // namespace slipfront::server
