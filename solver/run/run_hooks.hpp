// What the caller of a run hands in besides the parameters: a progress callback, a cancel
// flag and a sink for the sampled interface fields (solver/run/sample_sink.hpp).
#pragma once

#include "solver/run/sample_sink.hpp"

#include <atomic>
#include <functional>

namespace slipfront {

struct Progress {
  double time = 0.0;     // simulated time reached [s]
  double duration = 0.0; // simulated time requested [s]
  long step = 0;
  long total_steps = 0; // steps if the run goes to `duration`
  double fraction = 0.0;
  double wall_s = 0.0;
  double steps_per_s = 0.0;
  double eta_s = 0.0; // wall time left if the run goes to `duration`
};

struct RunHooks {
  std::function<void(const Progress&)> on_progress; // called about every progress_interval_s
  double progress_interval_s = 0.5;
  const std::atomic<bool>* cancel = nullptr; // checked every step; run ends within one step
  SampleSink* sink = nullptr;
};

} // namespace slipfront
