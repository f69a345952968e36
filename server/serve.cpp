#include "server/serve.hpp"

#include "server/core/log.hpp"
#include "server/server_app.hpp"
#include "server/server_config.hpp"

#include <csignal>
#include <cstdio>
#include <iostream>
#include <pthread.h>

namespace slipfront::server {

int serve_main(int argc, char** argv) {
  ServerConfig config;
  try {
    config = parse_server_args(argc, argv);
  } catch (const UsageError& e) {
    if (std::string(e.what()).empty()) {
      std::cout << usage_text();
      return 0;
    }
    std::cerr << "slipfront serve: " << e.what() << "\n" << usage_text();
    return 2;
  }
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
    std::thread waiter([&] {
      int sig = 0;
      while (sigwait(&signals, &sig) == 0 && sig == SIGHUP)
        app.reload_tokens();
      log_info(std::string("received ") + (sig == SIGTERM ? "SIGTERM" : "SIGINT"));
      app.request_stop();
    });
    app.run_until_stopped();
    // The waiter returned after a signal; nothing else stops the server.
    waiter.join();
    return 0;
  } catch (const std::exception& e) {
    log_error(std::string("slipfront serve: ") + e.what());
    return 1;
  }
}

} // namespace slipfront::server
