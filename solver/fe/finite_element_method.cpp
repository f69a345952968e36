#include "solver/fe/finite_element_method.hpp"

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
