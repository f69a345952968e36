// The spectral boundary-integral method's entry in the registry of methods
// (solver/methods.hpp): the elastic half-space, or two, with only the interface discretised.
#include "solver/mesh_size.hpp"
#include "solver/spectral/spectral_method.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <thread>

namespace slipfront::spectral {

namespace {

// The largest c_p / c_s of a spectral_bi job (poisson_ratio up to 0.49995): the kernel's
// quadrature grows with it (solver/spectral/half_space_kernels.cpp).
constexpr double max_wave_speed_ratio = 100.0;

std::unique_ptr<RuptureMethod> make(const SimulationParams& params) {
  const int threads =
      params.threads > 0 ? params.threads : int(std::max(1u, std::thread::hardware_concurrency()));
  return std::make_unique<SpectralMethod>(params, threads);
}

TimeStepBounds time_step_bounds(const SimulationParams& params) {
  const double dt = SpectralMethod::time_step(params);
  return {dt, dt};
}

std::string describe(const SimulationParams& params) {
  char text[200];
  const bool two = params.lower.elastic(); // docs/spectral-bi.md "Two half-spaces"
  std::snprintf(text, sizeof text,
                "spectral boundary integral, %s (velocity-form memory "
                "truncated after %g mode periods), dt = %g dx / %s, %d corrector pass%s",
                two ? "two elastic half-spaces" : "elastic half-space",
                params.spectral.memory_periods, params.spectral.time_step_factor,
                two ? "max c_s" : "c_s", params.spectral.corrector_passes,
                params.spectral.corrector_passes == 1 ? "" : "es");
  return text;
}

std::string mesh_summary(const SimulationParams& params) {
  const Geometry& g = params.geometry;
  char mesh[200];
  std::snprintf(mesh, sizeof mesh,
                "mesh: %ld interface nodes, dx = %g m, half-space (spectral boundary integral)\n",
                std::lround(g.width * g.nodes_per_meter), 1.0 / g.nodes_per_meter);
  return std::string(mesh) + (params.lower.elastic() ? "lower solid: elastic half-space\n" : "");
}

} // namespace

const MethodEntry& method_entry() {
  static const MethodEntry entry{
      .method = Method::spectral_bi,
      .label = "BI",
      .heading = "spectral BI",
      .title = "spectral boundary integral",
      .description = "the elastic half-space by the spectral boundary-integral method, only "
                     "the interface discretised (docs/spectral-bi.md)",
      .run_cost = "seconds per run",
      .cost_rank = 0,
      .counterpart = Method::finite_element,
      .supports = {.rigid_base = true, .two_solids = true, .block_height = false},
      .time_step = {.safety_factor = false, .rule = "spectral_bi.time_step_factor * dx / c_s"},
      .wave_speeds = {.max_ratio = max_wave_speed_ratio,
                      .why = "the spectral_bi kernel allows (poisson_ratio at most 0.49995)"},
      .make = &make,
      .time_step_bounds = &time_step_bounds,
      .step_count_bound = &SpectralMethod::step_bound,
      .estimated_memory_bytes = &SpectralMethod::estimated_memory_bytes,
      .estimated_work = &SpectralMethod::estimated_work,
      .cost_terms = {{{"lag_step_s", &RunWork::lag_steps},
                      {"transform_step_s", &RunWork::transform_steps},
                      {"interface_step_s", &RunWork::interface_steps},
                      {"rate_solve_s", &RunWork::rate_solves}}},
      .discretisation = "spectral boundary integral",
      .describe = &describe,
      .mesh_summary = &mesh_summary,
  };
  return entry;
}

} // namespace slipfront::spectral
