// Blocking work stays off the I/O threads: over real loopback HTTP, a request whose handler
// blocks (as a slow database write or a large HDF5 read would) does not hold up a cheap
// request on another connection, with a single I/O thread. Without the blocking-work pool
// the same cheap request waits (the control case, which shows that the test can fail). And
// the server's own heavy routes are the offloaded ones.
#include "server/core/server_stats.hpp"
#include "server/http/http_session.hpp"
#include "server/http/listener.hpp"
#include "server/http/responses.hpp"
#include "server/http/router.hpp"
#include "server/server_app.hpp"

#include "temp_dir.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <boost/asio/thread_pool.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/time.h>
#include <unistd.h>

#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <thread>

namespace slipfront::server {
namespace {

using namespace std::chrono_literals;

// Sends `request` (with "Connection: close") to 127.0.0.1:port and returns what comes back
// until the server closes; "" if nothing arrived within `timeout`.
std::string exchange(unsigned short port, const std::string& request,
                     std::chrono::milliseconds timeout) {
  const int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  if (fd < 0) return "";
  timeval tv{};
  tv.tv_sec = static_cast<long>(timeout.count() / 1000);
  tv.tv_usec = static_cast<long>(timeout.count() % 1000) * 1000;
  ::setsockopt(fd, SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
  sockaddr_in addr{};
  addr.sin_family = AF_INET;
  addr.sin_port = htons(port);
  addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  std::string answer;
  if (::connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0 &&
      ::send(fd, request.data(), request.size(), 0) == static_cast<ssize_t>(request.size())) {
    char buf[4096];
    for (ssize_t n; (n = ::recv(fd, buf, sizeof buf, 0)) > 0;)
      answer.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return answer;
}

std::string request_text(const std::string& method, const std::string& target) {
  std::string text = method;
  text += " ";
  text += target;
  text += " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\nContent-Length: 0\r\n\r\n";
  return text;
}

// A router with POST /slow, whose handler blocks until release() (a route of another method
// than GET: offloaded without asking), and GET /healthz, answered at once. A listener on an
// ephemeral loopback port served by one I/O thread.
class SlowAndCheapServer {
public:
  explicit SlowAndCheapServer(bool with_pool) {
    router_.add(http::verb::post, "/slow", [this](RequestContext& rc) {
      entered_.set_value();
      released_.wait();
      return Response(json_response(rc.request, http::status::ok, {{"slow", true}}));
    });
    router_.add(http::verb::get, "/healthz", [](RequestContext& rc) {
      return Response(json_response(rc.request, http::status::ok, {{"status", "ok"}}));
    });
    SessionLimits limits;
    if (with_pool) limits.offload_pool = &pool_;
    listener_ = std::make_shared<Listener>(
        ioc_, boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0),
        router_, stats_, limits);
    listener_->run();
    io_thread_ = std::thread([this] { ioc_.run(); });
  }
  ~SlowAndCheapServer() {
    release();
    listener_->stop();
    ioc_.stop();
    io_thread_.join();
    pool_.join();
  }
  unsigned short port() const { return listener_->local_endpoint().port(); }
  void wait_entered() { entered_future_.wait(); }
  void release() {
    if (!released_set_) released_promise_.set_value();
    released_set_ = true;
  }

private:
  Router router_;
  ServerStats stats_;
  boost::asio::io_context ioc_;
  boost::asio::thread_pool pool_{1};
  std::shared_ptr<Listener> listener_;
  std::thread io_thread_;
  std::promise<void> entered_;
  std::shared_future<void> entered_future_ = entered_.get_future().share();
  std::promise<void> released_promise_;
  std::shared_future<void> released_ = released_promise_.get_future().share();
  bool released_set_ = false;
};

TEST(BlockingWork, ASlowHandlerDoesNotHoldUpACheapRequest) {
  SlowAndCheapServer server(true);
  auto slow = std::async(std::launch::async, [&] {
    return exchange(server.port(), request_text("POST", "/slow"), 30s);
  });
  server.wait_entered(); // the slow handler is running (and blocked)
  const std::string health = exchange(server.port(), request_text("GET", "/healthz"), 10s);
  EXPECT_EQ(health.rfind("HTTP/1.1 200", 0), 0u) << health;
  EXPECT_NE(health.find("\"status\":\"ok\""), std::string::npos) << health;
  EXPECT_EQ(slow.wait_for(0s), std::future_status::timeout); // still blocked meanwhile
  server.release();
  const std::string answer = slow.get();
  EXPECT_EQ(answer.rfind("HTTP/1.1 200", 0), 0u) << answer;
}

// The control: the same slow handler on the only I/O thread blocks the cheap request.
TEST(BlockingWork, WithoutThePoolTheCheapRequestWaits) {
  SlowAndCheapServer server(false);
  auto slow = std::async(std::launch::async, [&] {
    return exchange(server.port(), request_text("POST", "/slow"), 30s);
  });
  server.wait_entered();
  EXPECT_EQ(exchange(server.port(), request_text("GET", "/healthz"), 1s), "");
  server.release();
  EXPECT_EQ(slow.get().rfind("HTTP/1.1 200", 0), 0u);
}

TEST(BlockingWork, TheServersHeavyRoutesAreOffloaded) {
  testing::TempDir dir("slipfront-blocking-");
  ServerConfig config;
  config.port = 0;
  config.workers = 1;
  config.io_threads = 1;
  config.data_dir = dir.str();
  ServerApp app(config);
  app.start();
  auto offloaded = [&](http::verb method, const std::string& target) {
    Request req{method, target, 11};
    return app.router().offloaded(req);
  };
  const std::string job = "/api/v1/jobs/0123456789abcdef0123456789abcdef";
  // Database writes, listings, HDF5 reads, stored fronts.
  EXPECT_TRUE(offloaded(http::verb::post, "/api/v1/jobs"));
  EXPECT_TRUE(offloaded(http::verb::post, job + "/cancel"));
  EXPECT_TRUE(offloaded(http::verb::post, "/api/v1/studies"));
  EXPECT_TRUE(offloaded(http::verb::get, "/api/v1/jobs?status=queued"));
  EXPECT_TRUE(offloaded(http::verb::get, job + "/fields/slip?max_points=10"));
  EXPECT_TRUE(offloaded(http::verb::head, job + "/fields/slip"));
  EXPECT_TRUE(offloaded(http::verb::get, job + "/result.xdmf"));
  EXPECT_TRUE(offloaded(http::verb::get, job + "/front"));
  // Quick reads stay on the I/O threads.
  EXPECT_FALSE(offloaded(http::verb::get, "/healthz"));
  EXPECT_FALSE(offloaded(http::verb::get, job));
  EXPECT_FALSE(offloaded(http::verb::get, "/api/v1/openapi.json"));
  app.shutdown();
}

} // namespace
} // namespace slipfront::server
