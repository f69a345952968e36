// One run: the rupture method the job asks for, stepped by the time loop; and the size
// and memory estimates of a run.
#include "solver/simulation.hpp"

#include "solver/make_rupture_method.hpp"
#include "solver/mesh_size.hpp"
#include "solver/spectral/spectral_model.hpp"
#include "solver/stable_time_step.hpp"
#include "solver/thread_team.hpp"
#include "solver/time_loop.hpp"

#include <chrono>
#include <memory>

namespace slipfront {

double resolved_height(const SimulationParams& params) {
  return mesh_size(params).height;
}

double estimated_memory_bytes(const SimulationParams& params) {
  if (params.method == Method::spectral_bi)
    return spectral::SpectralModel::estimated_memory_bytes(params);
  const MeshSize m = mesh_size(params);
  const double nodes = double(m.nx + 2) * m.ny;
  // u and v, two components each; with the mesh damping also w = u + a v.
  const double fields = (params.fe.mesh_damping > 0 ? 6.0 : 4.0) * 8.0 * nodes;
  const double interface = 24.0 * 8.0 * m.nx; // interface fields, front, buffers
  // Probe records (4 doubles a step) for the longest possible run.
  const double records = 4.0 * 8.0 * step_count_bound(params);
  const double sample_buffer = 64.0 * 6.0 * 8.0 * m.nx; // a chunk of samples in the writer
  const double baseline = 16.0e6;                       // code, libraries, HDF5 caches
  return fields + interface + records + sample_buffer + baseline;
}

TimeStepBounds time_step_bounds(const SimulationParams& params) {
  if (params.method == Method::spectral_bi) {
    const double dt = spectral::SpectralModel::time_step(params);
    return {dt, dt};
  }
  // The damped step decreases with dt0 (stable_time_step.hpp), so the lower bound of dt0
  // gives a lower bound of the damped step too.
  const double dx = 1.0 / params.geometry.nodes_per_meter;
  const double c_p = params.material.p_wave_speed();
  const double damping_a = params.fe.mesh_damping * dx / params.material.s_wave_speed();
  const double safety = params.time.safety_factor;
  return {safety * damped_stable_time_step(0.5 * dx / c_p, damping_a), safety * dx / c_p};
}

double step_count_bound(const SimulationParams& params) {
  if (params.method == Method::spectral_bi) return spectral::SpectralModel::step_bound(params);
  return params.time.duration / time_step_bounds(params).shortest;
}

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks) {
  // The wall time counts the set-up (the stable step's power iteration) too; the model is
  // built with denormals flushed, as it is stepped.
  const auto started = std::chrono::steady_clock::now();
  FloatModeGuard float_mode;
  const std::unique_ptr<RuptureMethod> method = make_rupture_method(params);
  return run_time_loop(*method, params, hooks, started);
}

} // namespace slipfront
