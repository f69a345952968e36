// The interface every rupture method offers to the time loop (solver/time_loop.hpp):
// the explicit finite elements today (solver/fe_method.hpp), a spectral boundary-integral
// method next. The loop steps the method and reads the interface after each step.
#pragma once

#include "solver/interface_fields.hpp"
#include "solver/mesh_info.hpp"

#include <string>
#include <vector>

namespace slipfront {

// One discretised interface problem advanced in time (FE today, spectral BI next).
class RuptureMethod {
public:
  virtual ~RuptureMethod() = default;
  virtual void step(bool compute_energy) = 0; // t_n -> t_{n+1}
  virtual double dt() const = 0;
  virtual const InterfaceFields& interface() const = 0; // after the step: quantities of step n
  virtual const EnergyBalance& energy() const = 0;
  virtual MeshInfo mesh_info() const = 0; // what was actually run
  // Warnings the method adds at the end of a run (FE: the top-reflection warning).
  virtual std::vector<std::string> end_warnings(double /*simulated_time*/) const { return {}; }
};

} // namespace slipfront
