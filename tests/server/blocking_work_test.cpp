// Blocking work stays off the I/O threads: over real loopback HTTP, a request whose handler
// blocks (as a slow database write or a large HDF5 read would) does not hold up a cheap
// request on another connection, with a single I/O thread. Without the blocking-work pool
// the same cheap request waits (the control case, which shows that the test can fail).
// Exports beyond the bound are refused at once while submissions pass. And
// the server's own heavy routes run on the pools they should.
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

#include <atomic>
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
// than GET: on the write pool without asking), and GET /healthz, answered at once. A listener on an
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
    if (with_pool) limits.pools.writes = &pool_;
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

// GET /export blocks until release() and runs on an export pool of one thread (as
// --max-exports 1); POST /submit runs on the write pool and answers at once.
class ExportingServer {
public:
  ExportingServer() {
    router_.add(
        http::verb::get, "/export",
        [this](RequestContext& rc) {
          if (!entered_once_.exchange(true)) entered_.set_value();
          released_.wait();
          return Response(json_response(rc.request, http::status::ok, {{"export", true}}));
        },
        Runs::export_pool);
    router_.add(http::verb::post, "/submit", [](RequestContext& rc) {
      return Response(json_response(rc.request, http::status::created, {{"submitted", true}}));
    });
    SessionLimits limits;
    limits.pools = {&reads_, &writes_, &exports_};
    listener_ = std::make_shared<Listener>(
        ioc_, boost::asio::ip::tcp::endpoint(boost::asio::ip::make_address("127.0.0.1"), 0),
        router_, stats_, limits);
    listener_->run();
    io_thread_ = std::thread([this] { ioc_.run(); });
  }
  ~ExportingServer() {
    release();
    listener_->stop();
    ioc_.stop();
    io_thread_.join();
    exports_.join();
    writes_.join();
    reads_.join();
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
  boost::asio::thread_pool reads_{1};
  boost::asio::thread_pool writes_{1};
  BoundedPool exports_{1};
  std::shared_ptr<Listener> listener_;
  std::thread io_thread_;
  std::atomic<bool> entered_once_{false};
  std::promise<void> entered_;
  std::shared_future<void> entered_future_ = entered_.get_future().share();
  std::promise<void> released_promise_;
  std::shared_future<void> released_ = released_promise_.get_future().share();
  bool released_set_ = false;
};

TEST(BlockingWork, AnExportPastTheBoundIsRefusedAndSubmissionsPass) {
  ExportingServer server;
  auto first = std::async(std::launch::async, [&] {
    return exchange(server.port(), request_text("GET", "/export"), 30s);
  });
  server.wait_entered(); // the one export thread is taken
  const std::string second = exchange(server.port(), request_text("GET", "/export"), 10s);
  EXPECT_EQ(second.rfind("HTTP/1.1 503", 0), 0u) << second;
  EXPECT_NE(second.find("Retry-After: 1"), std::string::npos) << second;
  EXPECT_NE(second.find("--max-exports"), std::string::npos) << second;
  const std::string submit = exchange(server.port(), request_text("POST", "/submit"), 10s);
  EXPECT_EQ(submit.rfind("HTTP/1.1 201", 0), 0u) << submit;
  EXPECT_EQ(first.wait_for(0s), std::future_status::timeout); // still exporting meanwhile
  server.release();
  EXPECT_EQ(first.get().rfind("HTTP/1.1 200", 0), 0u);
  // The thread is free again: the next export is served.
  std::string third;
  for (int attempt = 0; attempt < 50; ++attempt) { // the pool counts it free just after
    third = exchange(server.port(), request_text("GET", "/export"), 10s);
    if (third.rfind("HTTP/1.1 200", 0) == 0) break;
    std::this_thread::sleep_for(20ms);
  }
  EXPECT_EQ(third.rfind("HTTP/1.1 200", 0), 0u) << third;
}

TEST(BoundedPool, RunsAtMostItsLimitAtOnce) {
  BoundedPool pool(2);
  std::promise<void> release;
  std::shared_future<void> released = release.get_future().share();
  std::atomic<int> started{0};
  auto blocked = [&] {
    ++started;
    released.wait();
  };
  EXPECT_TRUE(pool.try_post(blocked));
  EXPECT_TRUE(pool.try_post(blocked));
  EXPECT_FALSE(pool.try_post([&] { ++started; })); // refused, never run
  release.set_value();
  pool.join();
  EXPECT_EQ(started.load(), 2);
}

TEST(BlockingWork, TheServersRoutesRunOnTheirPools) {
  testing::TempDir dir("slipfront-blocking-");
  ServerConfig config;
  config.port = 0;
  config.workers = 1;
  config.io_threads = 1;
  config.data_dir = dir.str();
  ServerApp app(config);
  app.start();
  auto runs = [&](http::verb method, const std::string& target) {
    Request req{method, target, 11};
    return app.router().runs(req);
  };
  const std::string job = "/api/v1/jobs/0123456789abcdef0123456789abcdef";
  // Database writes.
  EXPECT_EQ(runs(http::verb::post, "/api/v1/jobs"), Runs::write_pool);
  EXPECT_EQ(runs(http::verb::post, job + "/cancel"), Runs::write_pool);
  EXPECT_EQ(runs(http::verb::post, "/api/v1/studies"), Runs::write_pool);
  // Listings, HDF5 reads, stored fronts.
  EXPECT_EQ(runs(http::verb::get, "/api/v1/jobs?status=queued"), Runs::read_pool);
  EXPECT_EQ(runs(http::verb::get, "/api/v1/jobs?format=json&limit=1000"), Runs::read_pool);
  EXPECT_EQ(runs(http::verb::get, job + "/fields/slip?max_points=10"), Runs::read_pool);
  EXPECT_EQ(runs(http::verb::head, job + "/fields/slip"), Runs::read_pool);
  EXPECT_EQ(runs(http::verb::get, job + "/result.xdmf"), Runs::read_pool);
  EXPECT_EQ(runs(http::verb::get, job + "/front"), Runs::read_pool);
  // Exports.
  EXPECT_EQ(runs(http::verb::get, "/api/v1/jobs?format=csv"), Runs::export_pool);
  EXPECT_EQ(runs(http::verb::head, "/api/v1/jobs?where=n_d%3E5&format=ndjson"), Runs::export_pool);
  // A length fit computes over up to 200,000 samples: off the I/O threads, and on a bounded
  // pool of its own, never on the threads of submissions (and run archives on theirs).
  EXPECT_EQ(runs(http::verb::post, "/api/v1/length-fits"), Runs::fit_pool);
  EXPECT_EQ(runs(http::verb::get, "/api/v1/exports?ids=x"), Runs::export_pool);
  EXPECT_EQ(runs(http::verb::post, "/api/v1/imports"), Runs::write_pool);
  // Quick reads stay on the I/O threads.
  EXPECT_EQ(runs(http::verb::get, "/healthz"), Runs::io_thread);
  EXPECT_EQ(runs(http::verb::get, job), Runs::io_thread);
  EXPECT_EQ(runs(http::verb::get, "/api/v1/openapi.json"), Runs::io_thread);
  app.shutdown();
}

} // namespace
} // namespace slipfront::server
