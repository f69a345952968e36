#include "server/core/clock.hpp"

#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <string>

namespace slipfront::server {

std::string now_iso8601() {
  using namespace std::chrono;
  auto now = system_clock::now();
  auto ms = duration_cast<milliseconds>(now.time_since_epoch()).count() % 1000;
  std::time_t t = system_clock::to_time_t(now);
  std::tm tm{};
  gmtime_r(&t, &tm);
  char buf[64];
  std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d.%03dZ", tm.tm_year + 1900,
                tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, static_cast<int>(ms));
  return buf;
}

namespace {
double to_epoch_seconds(const std::string& text) {
  std::tm tm{};
  int ms = 0;
  if (std::sscanf(text.c_str(), "%d-%d-%dT%d:%d:%d.%dZ", &tm.tm_year, &tm.tm_mon, &tm.tm_mday,
                  &tm.tm_hour, &tm.tm_min, &tm.tm_sec, &ms) != 7)
    return std::nan("");
  tm.tm_year -= 1900;
  tm.tm_mon -= 1;
  return static_cast<double>(timegm(&tm)) + ms / 1000.0;
}
} // namespace

bool is_utc_iso8601(const std::string& text) {
  // "YYYY-MM-DDTHH:MM:SS" then an optional fraction, then "Z".
  constexpr const char* pattern = "dddd-dd-ddTdd:dd:dd";
  const std::size_t n = std::char_traits<char>::length(pattern);
  if (text.size() < n + 1 || text.size() > n + 11 || text.back() != 'Z') return false;
  for (std::size_t i = 0; i < n; ++i)
    if (pattern[i] == 'd' ? !std::isdigit(static_cast<unsigned char>(text[i]))
                          : text[i] != pattern[i])
      return false;
  const std::string fraction = text.substr(n, text.size() - n - 1);
  if (!fraction.empty()) {
    if (fraction.size() < 2 || fraction[0] != '.') return false;
    for (std::size_t i = 1; i < fraction.size(); ++i)
      if (!std::isdigit(static_cast<unsigned char>(fraction[i]))) return false;
  }
  auto field = [&](std::size_t at, std::size_t width) { return std::stoi(text.substr(at, width)); };
  std::tm tm{};
  tm.tm_year = field(0, 4) - 1900;
  tm.tm_mon = field(5, 2) - 1;
  tm.tm_mday = field(8, 2);
  tm.tm_hour = field(11, 2);
  tm.tm_min = field(14, 2);
  tm.tm_sec = field(17, 2);
  if (tm.tm_mon > 11 || tm.tm_mday < 1 || tm.tm_hour > 23 || tm.tm_min > 59 || tm.tm_sec > 60)
    return false;
  // The date exists: normalising it (31 April -> 1 May) changes nothing.
  std::tm copy = tm;
  const std::time_t t = timegm(&copy);
  std::tm back{};
  gmtime_r(&t, &back);
  return back.tm_mday == tm.tm_mday && back.tm_mon == tm.tm_mon;
}

double seconds_between(const std::string& from, const std::string& to) {
  return to_epoch_seconds(to) - to_epoch_seconds(from);
}

std::string host_name() {
  char buf[256] = {};
  if (gethostname(buf, sizeof buf - 1) != 0) return "unknown";
  return buf;
}

} // namespace slipfront::server
