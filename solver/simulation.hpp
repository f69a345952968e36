// Running one simulation: the entry point that the CLI and the server share.
//
//   RunResult r = run_simulation(params, hooks);
//
// It builds the rupture method the job asks for (its entry in solver/methods.hpp) and runs
// the time loop on it (run/time_loop.hpp). The run reports progress through a callback, stops
// cooperatively when the cancel flag is set, streams sampled interface fields to an
// optional SampleSink (the HDF5 writer; run/run_hooks.hpp), and returns the metrics of
// docs/metrics.md with the front profile and the probe records (run/run_result.hpp).
// Also the size estimates of a run that the job validation uses before it starts.
#pragma once

#include "solver/params.hpp"
#include "solver/run/run_hooks.hpp"
#include "solver/run/run_result.hpp"
#include "solver/run_work.hpp"
#include "solver/step_count.hpp"

namespace slipfront {

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks = {});

// Height used for the run: geometry.height, or for "auto" the smallest height for which a
// P wave leaving the interface at t = 0 and reflected by the top cannot come back before
// the run ends (2 h / c_p >= duration), rounded up to whole elements, plus one element.
double resolved_height(const SimulationParams& params);

// Bytes the run will hold in memory (fields, interface state, records, the stations' series);
// used by the job validation to refuse jobs above a limit before they start.
double estimated_memory_bytes(const SimulationParams& params);

// The time step of a run before it starts. BI's is exact: time_step_factor dx / c_s. FE's is
// safety_factor times the stable step of the mesh, found by power iteration when the run
// starts (solver/fe/stable_time_step.hpp). Undamped that step is dx / c_p on every mesh
// (tests/solver/fe/stable_time_step_test.cpp): the longest; the shortest takes half of it, the
// margin the memory and result-size estimates have always kept, and the mesh damping's
// shortening. In double: inf or 0 for an impossible job.
// (TimeStepBounds: solver/step_count.hpp.)
TimeStepBounds time_step_bounds(const SimulationParams& params);

// An upper bound of the steps of a run that goes to `duration` (duration / the shortest
// step; BI: its exact count), in double: beyond every integer type for an impossible job.
double step_count_bound(const SimulationParams& params);

// The work of a run up to simulated time `until` (the duration when negative): the counts
// the cost model of api/cost_estimate.hpp times (solver/run_work.hpp).
RunWork estimated_work(const SimulationParams& params, double until = -1.0);

// The version string compiled into this build (project version + git describe).
const char* code_version();

} // namespace slipfront
