// The explicit finite-element method as a RuptureMethod: owns the mesh stepper
// (solver/fe/mesh_stepper.hpp: the mesh, its state and the step) and the team of threads
// that steps it.
#pragma once

#include "solver/fe/mesh_stepper.hpp"
#include "solver/method_entry.hpp"
#include "solver/params.hpp"
#include "solver/run_work.hpp"
#include "solver/rupture_method.hpp"
#include "solver/step_count.hpp"
#include "solver/thread_team.hpp"

namespace slipfront::fe {

// Steps each thread carries in one trip over the mesh (solver/fe/level_pipeline.hpp). The rows
// between a thread's first and last step (2 per step; u and v, 32 B per node) stay in its
// cache; docs/performance.md §3b measured 1 to 16 (bench/roofline.cpp).
inline constexpr int kFeStepsPerThreadPerTrip = 4;

class FiniteElementMethod : public RuptureMethod {
public:
  explicit FiniteElementMethod(const SimulationParams& params);

  void step(bool compute_energy) override { mesh_.step(team_, compute_energy); }
  int block_steps() const override { return threads_ * kFeStepsPerThreadPerTrip; }
  void step_block(const std::vector<bool>& energy) override { mesh_.advance(team_, energy); }
  const InterfaceFields& interface_after(int k) const override { return mesh_.interface_after(k); }
  const EnergyBalance& energy_after(int k) const override { return mesh_.energy_after(k); }
  double dt() const override { return mesh_.dt(); }
  const InterfaceFields& interface() const override { return mesh_.interface(); }
  const EnergyBalance& energy() const override { return mesh_.energy(); }
  MeshInfo mesh_info() const override;
  // A P wave reflected by the top (or the lower block's bottom) reaches the interface at
  // t = 2h/c_p; plain Coulomb friction between two different solids is ill-posed.
  std::vector<std::string> end_warnings(double simulated_time) const override;

  // The time step's bounds before the run (solver/simulation.hpp, time_step_bounds), an upper
  // bound of the steps of a run that goes to `duration` (duration / the shortest step), and
  // the bytes the run will hold (fields, interface, records, buffers).
  static TimeStepBounds time_step_bounds(const SimulationParams& params);
  static double step_count_bound(const SimulationParams& params);
  static double estimated_memory_bytes(const SimulationParams& params);
  // The work of a run up to simulated time `until` (solver/run_work.hpp): the nodes within
  // c_p t of the nucleation patch in each block, row by row, swept every step.
  static RunWork estimated_work(const SimulationParams& params, double until);

private:
  int threads_;
  MeshStepper mesh_;
  ThreadTeam team_;
  std::string ill_posed_warning_; // plain Coulomb between two different solids, else empty
};

// The method's entry in the registry of methods (solver/methods.hpp; fe_entry.cpp).
const MethodEntry& method_entry();

} // namespace slipfront::fe
