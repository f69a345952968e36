#include "server/core/log.hpp"

#include "server/core/clock.hpp"

#include <chrono>
#include <cstdio>
#include <mutex>

namespace slipfront::server {

namespace {

std::mutex log_mutex;

// What a log line can carry comes partly from users (job names, request targets): control
// characters are written as \xNN so that a name holding "\n...error..." cannot forge a line.
std::string escape_controls(const std::string& text) {
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7f) {
      static const char* hex = "0123456789abcdef";
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 0xf];
    } else {
      out += static_cast<char>(c);
    }
  }
  return out;
}

// A line identical to the previous one within `repeat_window` is counted, not written (an
// accept loop failing with EMFILE would otherwise write megabytes of the same line); the
// count is written with the next different line or the next copy after the window.
constexpr auto repeat_window = std::chrono::seconds(10);
std::string last_line;
std::chrono::steady_clock::time_point last_written;
unsigned long repeats = 0;

void write(const char* level, const std::string& message) {
  std::string text = std::string(level) + " " + escape_controls(message);
  const auto now = std::chrono::steady_clock::now();
  std::lock_guard lock(log_mutex);
  if (text == last_line && now - last_written < repeat_window) {
    ++repeats;
    return;
  }
  std::string out;
  if (repeats > 0)
    out = now_iso8601() + " info (the previous line was repeated " + std::to_string(repeats) +
          " more time(s))\n";
  out += now_iso8601() + " " + text + "\n";
  repeats = 0;
  last_line = std::move(text);
  last_written = now;
  std::fputs(out.c_str(), stderr);
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
