// Running one simulation: the entry point that the CLI and the server share.
//
//   RunResult r = run_simulation(params, hooks);
//
// It builds the rupture method (make_rupture_method.hpp) and runs the time loop on it
// (time_loop.hpp).
// The run reports progress through a callback, stops cooperatively when the cancel flag
// is set, streams sampled interface fields to an optional SampleSink (the HDF5 writer),
// and returns the metrics of SPEC §2 with the front profile and the probe records.
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/mesh_info.hpp"
#include "solver/params.hpp"
#include "solver/run/metrics.hpp"
#include "solver/run/records.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

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

// The sampled interface nodes (every `space_stride`-th node).
struct InterfaceLayout {
  std::vector<double> x1;
  long expected_samples = 0; // if the run goes to `duration`
  double sample_interval = 0.0;
};

// One time sample of the interface fields at the sampled nodes (SPEC §2 names).
struct InterfaceSample {
  double time = 0.0;
  std::vector<double> slip_velocity;    // V [m/s], positive towards +x1
  std::vector<double> slip;             // u1 at the interface [m]
  std::vector<double> shear_traction;   // tau1 [Pa] (initially tau1_0)
  std::vector<double> contact_pressure; // p [Pa] (initially |tau2_0|)
  std::vector<double> strength;         // tau_s [Pa]
  std::vector<std::int8_t> state;       // NodeState
};

// Receives the sampled interface fields as the run produces them.
class SampleSink {
public:
  virtual ~SampleSink() = default;
  virtual void begin(const InterfaceLayout& layout) = 0;
  virtual void write(const InterfaceSample& sample) = 0;
};

struct RunHooks {
  std::function<void(const Progress&)> on_progress; // called about every progress_interval_s
  double progress_interval_s = 0.5;
  const std::atomic<bool>* cancel = nullptr; // checked every step; run ends within one step
  SampleSink* sink = nullptr;
};

struct RunResult {
  Metrics metrics;
  FrontProfile front;
  ProbeRecords probes;
  EnergyRecords energy;
  MeshInfo mesh;
  bool cancelled = false;
};

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
