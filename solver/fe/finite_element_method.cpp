#include "solver/fe/finite_element_method.hpp"

#include "solver/fe/stable_time_step.hpp"
#include "solver/mesh_size.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

namespace slipfront::fe {

namespace {

int thread_count(const SimulationParams& params) {
  return params.threads > 0 ? params.threads
                            : int(std::max(1u, std::thread::hardware_concurrency()));
}

} // namespace

FiniteElementMethod::FiniteElementMethod(const SimulationParams& params)
    : threads_(thread_count(params)), mesh_(params), team_(threads_),
      p_wave_speed_(params.material.p_wave_speed()), top_(params.top) {}

TimeStepBounds FiniteElementMethod::time_step_bounds(const SimulationParams& params) {
  // Undamped the stable step is dx / c_p on every mesh (the longest); the shortest takes half
  // of it. The damped step decreases with dt0 (stable_time_step.hpp), so the lower bound of
  // dt0 gives a lower bound of the damped step too. dx as mesh_size(params).dx, without the mesh.
  const double dx = 1.0 / params.geometry.nodes_per_meter;
  const double c_p = params.material.p_wave_speed();
  const double damping_a = params.fe.mesh_damping * dx / params.material.s_wave_speed();
  const double safety = params.time.safety_factor;
  return {safety * damped_stable_time_step(0.5 * dx / c_p, damping_a), safety * dx / c_p};
}

double FiniteElementMethod::step_count_bound(const SimulationParams& params) {
  return params.time.duration / time_step_bounds(params).shortest;
}

double FiniteElementMethod::estimated_memory_bytes(const SimulationParams& params) {
  const MeshSize m = mesh_size(params);
  const double nodes = double(m.nx + 2) * m.ny;
  // u and v, two components each; with the mesh damping also w = u + a v.
  const double fields = (params.fe.mesh_damping > 0 ? 6.0 : 4.0) * 8.0 * nodes;
  // interface fields, per-node parameters and friction state, front, buffers
  const double interface = 36.0 * 8.0 * m.nx;
  // Probe records (4 doubles a step) for the longest possible run.
  const double records = 4.0 * 8.0 * step_count_bound(params);
  const double sample_buffer = 64.0 * 6.0 * 8.0 * m.nx; // a chunk of samples in the writer
  const double baseline = 16.0e6;                       // code, libraries, HDF5 caches
  return fields + interface + records + sample_buffer + baseline;
}

MeshInfo FiniteElementMethod::mesh_info() const {
  return {mesh_.nx(),        mesh_.ny(), mesh_.dx(), mesh_.height(),
          mesh_.stable_dt(), mesh_.dt(), threads_};
}

std::vector<std::string> FiniteElementMethod::end_warnings(double simulated_time) const {
  const double reflection_time = 2.0 * mesh_.height() / p_wave_speed_;
  if (!(simulated_time > reflection_time)) return {};
  char msg[300];
  std::snprintf(
      msg, sizeof msg,
      "h = %.4g m is small for this run: a P wave reflected by the top reaches the interface "
      "at t = 2h/c_p = %.4g s, before the run ended at %.4g s%s",
      mesh_.height(), reflection_time, simulated_time,
      top_ == TopBoundary::absorbing
          ? " (the absorbing top weakens, but does not remove, the reflection)"
          : "");
  return {msg};
}

} // namespace slipfront::fe
