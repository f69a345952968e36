// Counting time steps without overflow. A count is computed in double and becomes an integer
// only once it is finite and in range: converting a double beyond the range of an integer
// type is undefined behaviour (a step count of 1e302 once became a negative memory estimate
// and a run of 0 steps).
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace slipfront {

// The shortest and longest time step a run may take, known before it starts
// (solver/simulation.hpp, time_step_bounds). In double: inf or 0 for an impossible job.
struct TimeStepBounds {
  double shortest = 0.0; // [s]
  double longest = 0.0;  // [s]
};

// The most time steps a run may take (docs/api-job-spec.md, "Limits of a run"): the job
// validation refuses a job that could take more, and a run never counts beyond it.
constexpr double max_run_steps = 1e9;

// The steps that reach `duration` with step `dt`: ceil(duration / dt), less a relative 1e-9
// so that a duration of a whole number of steps takes that number. In double: may be inf.
inline double steps_to_reach(double duration, double dt) {
  return std::ceil(duration / dt - 1e-9);
}

// `steps` as an integer; throws std::invalid_argument unless it is in [0, max_run_steps].
inline long checked_step_count(double steps) {
  if (!(steps >= 0.0 && steps <= max_run_steps))
    throw std::invalid_argument("the run would take " + std::to_string(steps) +
                                " time steps, outside [0, " + std::to_string(max_run_steps) +
                                "] (the job validation refuses such a job)");
  return static_cast<long>(steps);
}

// Every how many steps something recorded each `interval` is due: round(interval / dt), at
// least 1; an interval longer than any run gives max_run_steps (due at step 0 only).
inline int steps_per_interval(double interval, double dt) {
  const double steps = std::round(interval / dt);
  if (!(steps >= 1.0)) return 1; // also NaN
  return static_cast<int>(std::min(steps, max_run_steps));
}

} // namespace slipfront
