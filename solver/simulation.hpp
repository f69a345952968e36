// Running one simulation: the entry point that the CLI and the server share.
//
//   RunResult r = run_simulation(params, hooks);
//
// It builds the rupture method the job asks for (make_rupture_method.hpp) and runs the time
// loop on it (run/time_loop.hpp). The run reports progress through a callback, stops
// cooperatively when the cancel flag is set, streams sampled interface fields to an
// optional SampleSink (the HDF5 writer; run/run_hooks.hpp), and returns the metrics of
// docs/metrics.md with the front profile and the probe records (run/run_result.hpp).
// Also the size estimates of a run that the job validation uses before it starts.
#pragma once

#include "solver/params.hpp"
#include "solver/run/run_hooks.hpp"
#include "solver/run/run_result.hpp"

namespace slipfront {

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks = {});

// Height used for the run: geometry.height, or for "auto" the smallest height for which a
// P wave leaving the interface at t = 0 and reflected by the top cannot come back before
// the run ends (2 h / c_p >= duration), rounded up to whole elements, plus one element.
double resolved_height(const SimulationParams& params);

// Bytes the run will hold in memory (fields, interface state, records); used by the job
// validation to refuse jobs above a limit before they start.
double estimated_memory_bytes(const SimulationParams& params);

// An upper bound of the steps of a run that goes to `duration`: FE's stable step is above
// 0.5 dx / c_p, BI's step is time_step_factor dx / c_s.
double step_count_bound(const SimulationParams& params);

// The version string compiled into this build (project version + git describe).
const char* code_version();

} // namespace slipfront
