// The explicit finite-element method (solver/rupture_model.hpp) as a RuptureMethod: owns
// the model and the team of threads that steps it.
#pragma once

#include "solver/params.hpp"
#include "solver/rupture_method.hpp"
#include "solver/rupture_model.hpp"
#include "solver/thread_team.hpp"

namespace slipfront {

class FiniteElementMethod : public RuptureMethod {
public:
  explicit FiniteElementMethod(const SimulationParams& params);

  void step(bool compute_energy) override { model_.step(team_, compute_energy); }
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
