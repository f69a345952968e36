#include "server/serve.hpp"

#include "server/core/log.hpp"
#include "server/server_app.hpp"
#include "server/server_config.hpp"

#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <pthread.h>
#include <thread>

namespace slipfront::server {

namespace {

// The thread that reloads the token file when SIGHUP asks (ServerApp::reload_tokens).
class TokenReloads {
public:
  explicit TokenReloads(ServerApp& app) : thread_([this, &app] { loop(app); }) {}
  ~TokenReloads() { stop(); }
  void request() {
    std::lock_guard lock(mutex_);
    pending_ = true;
    wake_.notify_one();
  }
  // Ends the thread; one stuck in a read (a hung mount) is left behind, the process exits.
  void stop() {
    if (!thread_.joinable()) return;
    {
      std::lock_guard lock(mutex_);
      stopping_ = true;
      wake_.notify_one();
      if (reading_) {
        thread_.detach();
        return;
      }
    }
    thread_.join();
  }

private:
  void loop(ServerApp& app) {
    std::unique_lock lock(mutex_);
    for (;;) {
      wake_.wait(lock, [this] { return pending_ || stopping_; });
      if (stopping_) return;
      pending_ = false;
      reading_ = true;
      lock.unlock();
      app.reload_tokens();
      lock.lock();
      reading_ = false;
    }
  }

  std::mutex mutex_;
  std::condition_variable wake_;
  bool pending_ = false, stopping_ = false, reading_ = false;
  std::thread thread_;
};

} // namespace

int serve_main(const ServerConfig& config) {
  // SIGTERM, SIGINT (stop) and SIGHUP (reload the tokens) are taken by a dedicated thread
  // (sigwait), blocked everywhere else: the threads started below inherit the mask.
  sigset_t signals;
  sigemptyset(&signals);
  sigaddset(&signals, SIGTERM);
  sigaddset(&signals, SIGINT);
  sigaddset(&signals, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &signals, nullptr);
  std::signal(SIGPIPE, SIG_IGN);
  try {
    ServerApp app(config);
    app.start();
    auto ep = app.endpoint();
    std::string host = ep.address().to_string();
    if (ep.address().is_v6()) host = std::string("[").append(host).append("]");
    std::printf("listening on http://%s:%u\n", host.c_str(), static_cast<unsigned>(ep.port()));
    std::fflush(stdout);
    // SIGHUP only asks; the tokens are read on a thread of their own, so that a token file
    // that blocks can never keep SIGTERM from being handled.
    TokenReloads reloads(app);
    std::thread waiter([&] {
      int sig = 0;
      while (sigwait(&signals, &sig) == 0 && sig == SIGHUP)
        reloads.request();
      log_info(std::string("received ") + (sig == SIGTERM ? "SIGTERM" : "SIGINT"));
      app.request_stop();
    });
    app.run_until_stopped();
    // The waiter returned after a signal; nothing else stops the server.
    waiter.join();
    reloads.stop();
    return 0;
  } catch (const std::exception& e) {
    log_error(std::string("slipfront serve: ") + e.what());
    return 1;
  }
}

} // namespace slipfront::server
