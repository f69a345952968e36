// The time loop of one run, for any rupture method (the shape of a scene in uguca's
// examples), in five named phases (time_loop.cpp): set up the observers (front, divergence,
// probes, stations, energy, interface samples, arrest, progress); step a block of steps (one
// step, or several for a method that blocks them); record each step of the block; apply the
// stop rules (cancel, divergence, arrest) and report progress; derive the metrics
// (docs/metrics.md).
#pragma once

#include "solver/params.hpp"
#include "solver/run/run_hooks.hpp"
#include "solver/run/run_result.hpp"
#include "solver/rupture_method.hpp"

#include <chrono>

namespace slipfront {

// `started`: where the run's wall time counts from (run_simulation passes the time before
// it built the method, so that wall_time_s includes the set-up).
RunResult
run_time_loop(RuptureMethod& method, const SimulationParams& params, const RunHooks& hooks,
              std::chrono::steady_clock::time_point started = std::chrono::steady_clock::now());

} // namespace slipfront
