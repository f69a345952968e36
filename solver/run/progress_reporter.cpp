#include "solver/run/progress_reporter.hpp"

#include <algorithm>

namespace slipfront {

ProgressReporter::ProgressReporter(const RunHooks& hooks, double duration, double dt,
                                   long total_steps, Clock::time_point started)
    : on_progress_(hooks.on_progress), interval_(hooks.progress_interval_s), duration_(duration),
      dt_(dt), total_steps_(total_steps), started_(started) {}

double ProgressReporter::wall_seconds() const {
  return std::chrono::duration<double>(Clock::now() - started_).count();
}

void ProgressReporter::after_step(long n) {
  if (!on_progress_) return;
  const double wall = wall_seconds();
  if (!(wall - last_report_ >= interval_)) return;
  // The rate since the last report (a step's cost grows as the waves spread over the
  // block, so the mean since the start would promise too early an end in a long run);
  // the mean at the first report, or if the last one is too recent to time.
  const double window = wall - last_report_;
  const long window_steps = n + 1 - last_report_step_;
  const bool recent = last_report_step_ > 0 && window >= kMinRateWindowSeconds;
  const double rate = recent ? window_steps / window : (n + 1) / std::max(wall, 1e-9);
  last_report_ = wall;
  last_report_step_ = n + 1;
  Progress pr;
  pr.time = (n + 1) * dt_;
  pr.duration = duration_;
  pr.step = n + 1;
  pr.total_steps = total_steps_;
  pr.fraction = double(n + 1) / total_steps_;
  pr.wall_s = wall;
  pr.steps_per_s = rate;
  pr.eta_s = (total_steps_ - n - 1) / std::max(pr.steps_per_s, 1e-9);
  on_progress_(pr);
}

void ProgressReporter::final_report(long n, double simulated_time, double wall) const {
  if (!on_progress_) return;
  Progress pr{simulated_time,
              duration_,
              n,
              total_steps_,
              double(n) / std::max(total_steps_, 1L),
              wall,
              n / std::max(wall, 1e-9),
              0.0};
  on_progress_(pr);
}

} // namespace slipfront
