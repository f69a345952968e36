#include "server/log.hpp"

#include "server/clock.hpp"

#include <cstdio>
#include <mutex>

namespace slipfront::server {

namespace {
std::mutex log_mutex;
void write(const char* level, const std::string& message) {
  std::string line = now_iso8601() + " " + level + " " + message + "\n";
  std::lock_guard lock(log_mutex);
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
}
} // namespace

void log_info(const std::string& message) {
  write("info", message);
}
void log_error(const std::string& message) {
  write("error", message);
}

} // namespace slipfront::server
