// Progress of a run through RunHooks::on_progress: after a step at most every
// progress_interval_s of wall time, and once at the end. Also the run's wall clock.
// steps_per_s and the ETA are from the rate since the last report (the mean at the first
// report and at the end).
#pragma once

#include "solver/run/run_hooks.hpp"

#include <chrono>
#include <functional>

namespace slipfront {

class ProgressReporter {
public:
  using Clock = std::chrono::steady_clock;
  // total_steps: the steps if the run goes to `duration`; wall time counts from `started`.
  ProgressReporter(const RunHooks& hooks, double duration, double dt, long total_steps,
                   Clock::time_point started);

  double wall_seconds() const;
  void after_step(long step); // step n is done (n + 1 steps)
  // The run ended after `steps` steps at `simulated_time`, having taken `wall` seconds.
  void final_report(long steps, double simulated_time, double wall) const;

private:
  std::function<void(const Progress&)> on_progress_;
  double interval_;
  double duration_, dt_;
  long total_steps_;
  Clock::time_point started_;
  double last_report_ = -1e9;
  long last_report_step_ = 0; // steps done at the last report
  // Shorter windows time too few steps for a steady rate (thread hand-offs, load).
  static constexpr double kMinRateWindowSeconds = 0.2;
};

} // namespace slipfront
