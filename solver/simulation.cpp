// One run: the rupture method the job asks for, stepped by the time loop; and the size
// and memory estimates of a run.
#include "solver/simulation.hpp"

#include "solver/fe/stable_time_step.hpp"
#include "solver/make_rupture_method.hpp"
#include "solver/mesh_size.hpp"
#include "solver/run/time_loop.hpp"
#include "solver/spectral/spectral_method.hpp"
#include "solver/thread_team.hpp"

#include <chrono>
#include <memory>

namespace slipfront {

double resolved_height(const SimulationParams& params) {
  return mesh_size(params).height;
}

double estimated_memory_bytes(const SimulationParams& params) {
  if (params.method == Method::spectral_bi)
    return spectral::SpectralMethod::estimated_memory_bytes(params);
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

double step_count_bound(const SimulationParams& params) {
  if (params.method == Method::spectral_bi)
    return double(spectral::SpectralMethod::max_steps(params));
  // The stable step of a regular Q4 mesh is above 0.5 dx / c_p; the damped bound decreases
  // with dt0, so that lower bound of dt0 gives a lower bound of the damped step too.
  const double dx = mesh_size(params).dx;
  const double damping_a = params.fe.mesh_damping * dx / params.material.s_wave_speed();
  return params.time.duration /
         (params.time.safety_factor *
          fe::damped_stable_time_step(0.5 * dx / params.material.p_wave_speed(), damping_a));
}

RunResult run_simulation(const SimulationParams& params, const RunHooks& hooks) {
  // The wall time counts the set-up (the stable step's power iteration) too; the method is
  // built with denormals flushed, as it is stepped.
  const auto started = std::chrono::steady_clock::now();
  FloatModeGuard float_mode;
  const std::unique_ptr<RuptureMethod> method = make_rupture_method(params);
  return run_time_loop(*method, params, hooks, started);
}

} // namespace slipfront
