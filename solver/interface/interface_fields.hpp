// The state of the interface that every rupture method exposes after a step: the node
// states, the interface fields of the step and the energy balance since t = 0.
#pragma once

#include "solver/params.hpp"

#include <cstdint>
#include <vector>

namespace slipfront {

// Node state at the interface, as stored in /interface/state.
enum class NodeState : std::int8_t { stick = 0, slip = 1, open = 2 };

// The interface after a step, at time t_n: every quantity of step n.
struct InterfaceFields {
  std::vector<double> x1;             // node positions
  std::vector<double> velocity;       // V^n = (v^{n-1/2} + v^{n+1/2}) / 2 along x1
  std::vector<double> half_velocity;  // v^{n+1/2} along x1 (the velocity the next step uses)
  std::vector<double> slip;           // u1^n
  std::vector<double> opening;        // u2^n
  std::vector<double> shear_traction; // tau1^n = -C1/dx
  std::vector<double> pressure;       // p^n
  std::vector<double> strength;       // tau_s used in step n
  std::vector<std::int8_t> state;     // NodeState in step n
};

// Energy terms since t = 0 (per unit thickness) after the step; see docs/physics.md.
struct EnergyBalance {
  double kinetic = 0;       // 1/2 v^{n+1/2} M v^{n+1/2}
  double strain = 0;        // 1/2 u^n K u^{n+1}  (the quadratic form that leapfrog conserves)
  double external_work = 0; // work of the load changes: pre-stress release, nucleation, extra
  double dissipated = 0;    // friction and contact impacts, absorbing top
  // Of kinetic + strain, the part held by the lower solid (0 on the rigid plane); each
  // solid's part is checked for passivity on its own (solver/run/divergence_check.hpp).
  double lower_solid = 0;
};

} // namespace slipfront
