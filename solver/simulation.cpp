// One run: the rupture method the job asks for, stepped by the time loop; and the size
// and memory estimates of a run.
#include "solver/simulation.hpp"

#include "solver/mesh_size.hpp"
#include "solver/methods.hpp"
#include "solver/run/station_recorder.hpp"
#include "solver/run/time_loop.hpp"
#include "solver/thread_team.hpp"

#include <chrono>
#include <memory>

namespace slipfront {

double resolved_height(const SimulationParams& params) {
  return mesh_size(params).height;
}

double estimated_memory_bytes(const SimulationParams& params) {
  // The station records are the time loop's, the same for every method.
  const double stations = StationRecorder::record_bytes(params.stations, step_count_bound(params));
  return method_entry(params.method).estimated_memory_bytes(params) + stations;
}

TimeStepBounds time_step_bounds(const SimulationParams& params) {
  return method_entry(params.method).time_step_bounds(params);
}

double step_count_bound(const SimulationParams& params) {
  return method_entry(params.method).step_count_bound(params);
}

RunWork estimated_work(const SimulationParams& params, double until) {
  if (until < 0) until = params.time.duration;
  return method_entry(params.method).estimated_work(params, until);
}

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks) {
  // The wall time counts the set-up (the stable step's power iteration) too; the method is
  // built with denormals flushed, as it is stepped.
  const auto started = std::chrono::steady_clock::now();
  FloatModeGuard float_mode;
  const std::unique_ptr<RuptureMethod> method = method_entry(params.method).make(params);
  return run_time_loop(*method, params, hooks, started);
}

} // namespace slipfront
