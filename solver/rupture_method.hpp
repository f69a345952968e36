// The interface every rupture method offers to the time loop (solver/run/time_loop.hpp): the
// explicit finite elements (solver/fe/finite_element_method.hpp) and the spectral
// boundary-integral method (solver/spectral/spectral_method.hpp) implement it; a "method" in
// this code is always one of these. The loop steps the method and reads the interface after
// each step.
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/mesh_info.hpp"

#include <string>
#include <vector>

namespace slipfront {

// One discretised interface problem advanced in time.
class RuptureMethod {
public:
  virtual ~RuptureMethod() = default;
  virtual void step(bool compute_energy) = 0; // t_n -> t_{n+1}
  // Steps the method takes at once at most (FE: temporal blocking, one trip over the mesh
  // for several steps). step_block(energy) advances energy.size() <= block_steps() steps,
  // energy[k] saying whether step k of the block evaluates the energy terms; then
  // interface_after(k) and energy_after(k) are those after step k of the block.
  virtual int block_steps() const { return 1; }
  virtual void step_block(const std::vector<bool>& energy) { step(energy.front()); } // 1 step

  virtual const InterfaceFields& interface_after(int /*k*/) const { return interface(); }
  virtual const EnergyBalance& energy_after(int /*k*/) const { return energy(); }
  virtual double dt() const = 0;
  virtual const InterfaceFields& interface() const = 0; // after the step: quantities of step n
  virtual const EnergyBalance& energy() const = 0;
  virtual MeshInfo mesh_info() const = 0; // what was actually run
  // Warnings the method adds at the end of a run (FE: the top-reflection warning).
  virtual std::vector<std::string> end_warnings(double /*simulated_time*/) const { return {}; }
};

} // namespace slipfront
