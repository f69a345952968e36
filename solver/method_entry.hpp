// What a rupture method is besides its RuptureMethod: its names and labels, what it supports,
// its time-step rule, its size estimates and its factory. One entry per method, defined in the
// method's folder (solver/fe/fe_entry.cpp, solver/spectral/spectral_entry.cpp) and listed in
// the registry (solver/methods.hpp), which everything else asks instead of naming a method.
#pragma once

#include "solver/params.hpp"
#include "solver/run_work.hpp"
#include "solver/rupture_method.hpp"
#include "solver/step_count.hpp"

#include <array>
#include <limits>
#include <memory>
#include <string>

namespace slipfront {

// What a method can run; the job reader refuses the rest, naming the field.
struct MethodSupports {
  bool rigid_base = true; // the upper solid on the rigid plane (lower.solid "rigid")
  bool two_solids = true; // a second elastic solid below the interface (lower.solid "elastic")
  // Each solid is a block of finite height: geometry.height and top_boundary, lower.height and
  // bottom_boundary. False: the solids are half-spaces, which have neither.
  bool block_height = false;
};

// How a run's time step is set.
struct TimeStepRule {
  // True: dt = time.safety_factor × the stable step of the discrete system, found when the run
  // starts (known within bounds before it). False: dt is known exactly before the run, by
  // `rule`, and time.safety_factor is refused with it.
  bool safety_factor = false;
  const char* rule = ""; // e.g. "spectral_bi.time_step_factor * dx / c_s"
};

// The largest c_p / c_s a method can take (its kernel's quadrature, say), and why.
struct WaveSpeedLimit {
  double max_ratio = std::numeric_limits<double>::infinity();
  const char* why = ""; // "the spectral_bi kernel allows (poisson_ratio at most 0.49995)"
};

// A count of a run's work that the cost model times: "node_step_s" for RunWork::node_steps.
struct CostTerm {
  const char* name;
  double RunWork::*work;
};

struct MethodEntry {
  Method method;           // its name: the job's "method", the metrics' and the result file's
  const char* label;       // short, for table cells and legends: "FE", "BI"
  const char* heading;     // for a page's heading: "FE", "spectral BI"
  const char* title;       // in words: "finite elements", "spectral boundary integral"
  const char* description; // what it discretises (the job schema's words of "method")
  const char* run_cost;    // what one run costs, for a choice between methods
  int cost_rank;      // 0 for the cheapest per run at one n_d (a study's "auto" tries it first)
  Method counterpart; // the method a study compares its runs with (the same physics)
  MethodSupports supports;
  TimeStepRule time_step;
  WaveSpeedLimit wave_speeds;

  // Builds the method for a run (its threads from params.threads; 0: all hardware threads).
  std::unique_ptr<RuptureMethod> (*make)(const SimulationParams& params);
  // Before the run, in double (inf or 0 for an impossible job): the time step's bounds, an
  // upper bound of the steps of a run to time.duration, and the bytes the run will hold
  // (fields, interface, records, buffers; the stations' series are the time loop's, added by
  // estimated_memory_bytes of solver/simulation.hpp).
  TimeStepBounds (*time_step_bounds)(const SimulationParams& params);
  double (*step_count_bound)(const SimulationParams& params);
  double (*estimated_memory_bytes)(const SimulationParams& params);
  // The work of a run to `until` seconds, in the counts the cost model times (run_work.hpp).
  RunWork (*estimated_work)(const SimulationParams& params, double until);
  // The four counts of that work the cost model times besides the set-up
  // (api/cost_estimate.hpp): each its name in the model's file and its RunWork member.
  std::array<CostTerm, 4> cost_terms;
  // The discretisation in a phrase ("Q4 2x2 Gauss, lumped mass, central differences"), and
  // with the run's options ("...; top boundary: traction"): the metrics' method_description
  // before the friction law.
  const char* discretisation;
  std::string (*describe)(const SimulationParams& params);
  // What `slipfront validate` prints of the discretisation: "mesh: ...\n" and any more lines.
  std::string (*mesh_summary)(const SimulationParams& params);
};

} // namespace slipfront
