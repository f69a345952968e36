// The explicit finite-element method (solver/rupture_model.hpp) as a RuptureMethod: owns
// the model and the team of threads that steps it.
#pragma once

#include "solver/params.hpp"
#include "solver/rupture_method.hpp"
#include "solver/rupture_model.hpp"
#include "solver/thread_team.hpp"

namespace slipfront {

// Steps each thread carries in one trip over the mesh (solver/level_pipeline.hpp). The rows
// between a thread's first and last step (2 per step; u and v, 32 B per node) stay in its
// cache; docs/performance.md §3b measured 1 to 16 (bench/roofline.cpp).
inline constexpr int kFeStepsPerThreadPerTrip = 4;

class FiniteElementMethod : public RuptureMethod {
public:
  explicit FiniteElementMethod(const SimulationParams& params);

  void step(bool compute_energy) override { model_.step(team_, compute_energy); }
  int block_steps() const override { return threads_ * kFeStepsPerThreadPerTrip; }
  void step_block(const std::vector<bool>& energy) override { model_.advance(team_, energy); }
  const InterfaceFields& interface_after(int k) const override { return model_.interface_after(k); }
  const EnergyBalance& energy_after(int k) const override { return model_.energy_after(k); }
  double dt() const override { return model_.dt(); }
  const InterfaceFields& interface() const override { return model_.interface(); }
  const EnergyBalance& energy() const override { return model_.energy(); }
  MeshInfo mesh_info() const override;
  // A P wave reflected by the top reaches the interface at t = 2h/c_p.
  std::vector<std::string> end_warnings(double simulated_time) const override;

private:
  int threads_;
  RuptureModel model_;
  ThreadTeam team_;
  double p_wave_speed_;
  TopBoundary top_;
};

} // namespace slipfront
