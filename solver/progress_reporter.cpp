#include "solver/progress_reporter.hpp"

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
  last_report_ = wall;
  Progress pr{(n + 1) * dt_,
              duration_,
              n + 1,
              total_steps_,
              double(n + 1) / total_steps_,
              wall,
              (n + 1) / std::max(wall, 1e-9),
              0.0};
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
