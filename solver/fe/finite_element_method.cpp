#include "solver/fe/finite_element_method.hpp"

#include "solver/fe/stable_time_step.hpp"
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/ill_posedness.hpp"
#include "solver/interface/nucleation.hpp"
#include "solver/mesh_size.hpp"

#include <algorithm>
#include <cmath>
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
      ill_posed_warning_(bimaterial_coulomb_warning(params)) {}

namespace {

// The bounds of one block's stable step (time_step_bounds), without the mesh.
TimeStepBounds block_step_bounds(const Material& material, const SimulationParams& params) {
  // Undamped the stable step is dx / c_p on every mesh (the longest); the shortest takes half
  // of it. The damped step decreases with dt0 (stable_time_step.hpp), so the lower bound of
  // dt0 gives a lower bound of the damped step too. dx as mesh_size(params).dx.
  const double dx = 1.0 / params.geometry.nodes_per_meter;
  const double c_p = material.p_wave_speed();
  const double damping_a = params.fe.mesh_damping * dx / material.s_wave_speed();
  const double safety = params.time.safety_factor;
  return {safety * damped_stable_time_step(0.5 * dx / c_p, damping_a), safety * dx / c_p};
}

} // namespace

TimeStepBounds FiniteElementMethod::time_step_bounds(const SimulationParams& params) {
  const TimeStepBounds upper = block_step_bounds(params.material, params);
  if (!params.lower.elastic()) return upper;
  // The run takes the smaller of the two blocks' stable steps (mesh_stepper.cpp).
  const TimeStepBounds lower = block_step_bounds(params.lower.material, params);
  return {std::min(upper.shortest, lower.shortest), std::min(upper.longest, lower.longest)};
}

double FiniteElementMethod::step_count_bound(const SimulationParams& params) {
  return params.time.duration / time_step_bounds(params).shortest;
}

double FiniteElementMethod::estimated_memory_bytes(const SimulationParams& params) {
  const MeshSize m = mesh_size(params);
  double nodes = double(m.nx + 2) * m.ny;
  if (params.lower.elastic()) nodes += double(m.nx + 2) * lower_mesh_size(params).ny;
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

namespace {

// The rows and nodes of one block (nx x ny, element dx) within `reach` of the source interval
// of length `source` on the interface: row j at height j dx holds the interval grown by
// sqrt(reach^2 - (j dx)^2) each side, at most the whole row.
struct Swept {
  double rows = 0, nodes = 0;
};
Swept swept_within(double reach, double source, int nx, int ny, double dx) {
  Swept s;
  const int rows = std::min(ny, int(reach / dx) + 1);
  s.rows = rows;
  for (int j = 0; j < rows; ++j) {
    const double y = j * dx;
    const double half = std::sqrt(std::max(reach * reach - y * y, 0.0));
    s.nodes += std::min(double(nx), std::floor((source + 2 * half) / dx) + 1);
  }
  return s;
}

} // namespace

RunWork FiniteElementMethod::estimated_work(const SimulationParams& params, double until) {
  // The waves' reach runs a few elements ahead of c_p t (the discrete precursor, until it
  // underflows to exact zeros: docs/physics.md "Far field that the step skips").
  constexpr double precursor_elements = 3.0;
  constexpr int time_samples = 200; // the sum over steps, by the midpoint rule
  const MeshSize m = mesh_size(params);
  const double dx = m.dx;
  double dt = 0;
  for (const Material* block : {&params.material, &params.lower.material}) {
    if (block == &params.lower.material && !params.lower.elastic()) break;
    const double undamped = dx / block->p_wave_speed();
    const double damped =
        damped_stable_time_step(undamped, params.fe.mesh_damping * dx / block->s_wave_speed());
    dt = dt == 0 ? damped : std::min(dt, damped);
  }
  RunWork work;
  work.dt = params.time.safety_factor * dt;
  work.steps = steps_to_reach(until, work.dt);
  work.interface_steps = work.steps * m.nx;
  const CoefficientLaw& law = coefficient_law(params.friction);
  if (law.rate_dependent()) // a solve at each node in the predictor and in the corrector
    work.rate_solves = 2.0 * work.interface_steps;
  // The waves leave the nucleation patch, or the whole interface where the law slides from
  // the first step (rate and state at its initial slip rate: no far field stays quiet).
  Interval patch = nucleation_patch(params.nucleation);
  if (!law.starts_stuck()) patch = {-0.5 * params.geometry.width, 0.5 * params.geometry.width};
  if (!(patch.lo <= patch.hi) || !(work.steps > 0)) return work; // nothing ever moves
  const double source = patch.hi - patch.lo;
  double nodes = 0, rows = 0;
  for (int i = 0; i < time_samples; ++i) {
    const double t = (i + 0.5) / time_samples * until;
    Swept s = swept_within(params.material.p_wave_speed() * t + precursor_elements * dx, source,
                           m.nx, m.ny, dx);
    if (params.lower.elastic()) {
      const Swept lower =
          swept_within(params.lower.material.p_wave_speed() * t + precursor_elements * dx, source,
                       m.nx, lower_mesh_size(params).ny, dx);
      s.rows += lower.rows;
      s.nodes += lower.nodes;
    }
    nodes += s.nodes;
    rows += s.rows;
  }
  // The mesh damping adds the pass of w = u + a v to every node (docs/physics.md) and keeps
  // the steps from sharing a trip over the mesh: 2.7 times the time per node and step
  // (measured, the paper's scene at n_d = 20; docs/performance.md "Cost estimate").
  const double damping = params.fe.mesh_damping > 0 ? 2.7 : 1.0;
  work.node_steps = damping * work.steps * nodes / time_samples;
  work.row_steps = work.steps * rows / time_samples;
  return work;
}

MeshInfo FiniteElementMethod::mesh_info() const {
  MeshInfo info{mesh_.nx(),        mesh_.ny(), mesh_.dx(), mesh_.height(),
                mesh_.stable_dt(), mesh_.dt(), threads_};
  if (const ElasticBlock* lower = mesh_.lower()) {
    info.lower_ny = lower->ny();
    info.lower_height = lower->height();
  }
  return info;
}

namespace {

// The warning of a block whose far boundary reflects a P wave back before the run ended.
// `boundary`: "top" or "bottom"; `where`: "top" or "lower block's bottom".
std::vector<std::string> reflection_warning(const ElasticBlock& block, const char* boundary,
                                            const char* where, double simulated_time) {
  const double c_p = block.material().p_wave_speed();
  const double reflection_time = 2.0 * block.height() / c_p;
  if (!(simulated_time > reflection_time)) return {};
  const bool absorbing = block.far_boundary() != TopBoundary::traction;
  const char* absorber = block.far_boundary() == TopBoundary::pml
                             ? " (the perfectly matched layer at the "
                             : " (the absorbing ";
  char msg[320];
  std::snprintf(
      msg, sizeof msg,
      "h = %.4g m is small for this run: a P wave reflected by the %s reaches the interface "
      "at t = 2h/c_p = %.4g s, before the run ended at %.4g s%s%s%s",
      block.height(), where, reflection_time, simulated_time, absorbing ? absorber : "",
      absorbing ? boundary : "", absorbing ? " weakens, but does not remove, the reflection)" : "");
  return {msg};
}

} // namespace

std::vector<std::string> FiniteElementMethod::end_warnings(double simulated_time) const {
  std::vector<std::string> warnings =
      reflection_warning(mesh_.upper(), "top", "top", simulated_time);
  if (const ElasticBlock* lower = mesh_.lower())
    for (std::string& w :
         reflection_warning(*lower, "bottom", "lower block's bottom", simulated_time))
      warnings.push_back(std::move(w));
  if (!ill_posed_warning_.empty()) warnings.push_back(ill_posed_warning_);
  return warnings;
}

} // namespace slipfront::fe
