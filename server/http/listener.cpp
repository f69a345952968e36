#include "server/http/listener.hpp"

#include "server/core/log.hpp"

#include <boost/asio/post.hpp>
#include <boost/asio/strand.hpp>

namespace slipfront::server {

namespace net = boost::asio;
using tcp = net::ip::tcp;

Listener::Listener(net::io_context& ioc, const tcp::endpoint& endpoint, const Router& router,
                   ServerStats& stats, SessionLimits limits)
    : ioc_(ioc), acceptor_(net::make_strand(ioc)), router_(router), stats_(stats), limits_(limits),
      retry_timer_(acceptor_.get_executor()) {
  auto where = endpoint.address().to_string() + ":" + std::to_string(endpoint.port());
  beast::error_code ec;
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(net::socket_base::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(net::socket_base::max_listen_connections, ec);
  if (ec == net::error::address_in_use)
    throw std::runtime_error("cannot listen on " + where + ": " + ec.message() +
                             " (another server listens there: stop it, or give another --port; "
                             "--port 0 picks a free one)");
  if (ec) throw std::runtime_error("cannot listen on " + where + ": " + ec.message());
}

void Listener::run() {
  accept();
}

void Listener::stop() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] {
    beast::error_code ec;
    self->acceptor_.close(ec);
    self->retry_timer_.cancel();
  });
}

void Listener::accept() {
  acceptor_.async_accept(net::make_strand(ioc_),
                         beast::bind_front_handler(&Listener::on_accept, shared_from_this()));
}

void Listener::accept_later(std::chrono::milliseconds delay) {
  retry_timer_.expires_after(delay);
  retry_timer_.async_wait([self = shared_from_this()](beast::error_code ec) {
    if (!ec && self->acceptor_.is_open()) self->accept();
  });
}

void Listener::on_accept(beast::error_code ec, tcp::socket socket) {
  if (ec == net::error::operation_aborted || !acceptor_.is_open()) return;
  if (ec) {
    // Too many open files (or no memory): the connection stays in the backlog; retrying at
    // once would spin. The log writes a repeated line once (log.cpp).
    log_error("accept: " + ec.message() + "; accepting again in 100 ms");
    return accept_later(std::chrono::milliseconds(100));
  }
  if (*open_ >= limits_.max_connections) {
    // Over the cap: a short answer and close, so that clients (and health checks) learn it
    // at once instead of hanging in the backlog while the server runs out of descriptors.
    static const std::string busy =
        "HTTP/1.1 503 Service Unavailable\r\nServer: slipfront\r\nRetry-After: 1\r\n"
        "Content-Type: application/problem+json\r\nConnection: close\r\nContent-Length: 86\r\n"
        "\r\n{\"status\": 503, \"title\": \"Service Unavailable\", \"detail\": \"too many open "
        "connections\"}";
    beast::error_code wec;
    socket.non_blocking(true, wec);
    socket.write_some(net::buffer(busy), wec); // a fresh socket's buffer takes it whole
    socket.shutdown(tcp::socket::shutdown_both, wec);
    socket.close(wec);
    log_error("connection refused: " + std::to_string(limits_.max_connections) +
              " connections open (--max-connections)");
    return accept();
  }
  socket.set_option(tcp::no_delay(true), ec);
  std::make_shared<HttpSession>(std::move(socket), router_, stats_, limits_, open_)->run();
  accept();
}

} // namespace slipfront::server
