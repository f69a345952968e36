#include "app/progress_display.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>
#include <string>

namespace slipfront::app {

namespace {

constexpr int bar_width = 24;
constexpr auto plain_line_interval = std::chrono::seconds(5);

std::string format_duration(double seconds) {
  if (!std::isfinite(seconds) || seconds < 0.0) return "?";
  const long total = std::lround(seconds);
  char text[32];
  if (total >= 3600) {
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
  } else {
    std::snprintf(text, sizeof text, "%ld:%02ld", total / 60, total % 60);
  }
  return text;
}

} // namespace

std::string format_progress(const Progress& p) {
  const double fraction = std::clamp(p.fraction, 0.0, 1.0);
  const int filled = static_cast<int>(fraction * bar_width);
  std::string bar(bar_width, '.');
  bar.replace(0, filled, filled, '#');
  char text[224];
  std::snprintf(text, sizeof text,
                "[%s] %5.1f%%  t = %.3g / %.3g s  step %ld / %ld  %.0f steps/s  wall %s  ETA %s",
                bar.c_str(), 100.0 * fraction, p.time, p.duration, p.step, p.total_steps,
                p.steps_per_s, format_duration(p.wall_s).c_str(), format_duration(p.eta_s).c_str());
  return text;
}

std::string format_final(const Metrics& m, double duration) {
  char text[320];
  std::string what = to_string(m.outcome);
  if (m.outcome == Outcome::arrested && std::isfinite(m.arrest_position)) {
    char at[64];
    std::snprintf(at, sizeof at, " at x1 = %.4g m", m.arrest_position);
    what += at;
  }
  const bool early = m.simulated_time < duration * (1.0 - 1e-9);
  std::snprintf(text, sizeof text,
                "done: %s; t = %.4g of %.4g s simulated%s; %ld steps; wall %.3g s", what.c_str(),
                m.simulated_time, duration,
                early && m.outcome == Outcome::arrested ? " (stopped on arrest)" : "", m.steps,
                m.wall_time_s);
  return text;
}

ProgressDisplay::ProgressDisplay(std::ostream& out, bool terminal)
    : out_(out), terminal_(terminal), last_line_(std::chrono::steady_clock::now()) {}

void ProgressDisplay::update(const Progress& progress) {
  if (terminal_) {
    out_ << '\r' << format_progress(progress) << "\x1b[K" << std::flush; // redraw, clear the rest
    drawn_ = true;
    return;
  }
  const auto now = std::chrono::steady_clock::now();
  if (now - last_line_ < plain_line_interval) return;
  last_line_ = now;
  out_ << format_progress(progress) << std::endl;
}

void ProgressDisplay::finish() {
  if (terminal_ && drawn_) out_ << '\n' << std::flush;
}

} // namespace slipfront::app
