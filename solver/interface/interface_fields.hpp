// The state of the interface that every rupture method exposes after a step: the node
// states, the interface fields of the step and the energy balance since t = 0.
#pragma once

#include "solver/params.hpp"

#include <cmath>
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

// The uniform, stuck, pre-stressed initial state of nx interface nodes spaced dx from
// x_min: no motion, tau1 = tau1_0, p = |tau2_0|, tau_s(0) = mu p0 (docs/physics.md "Load",
// "Regularisation").
inline InterfaceFields resting_interface(const SimulationParams& params, int nx, double dx) {
  const double p0 = std::abs(params.loading.normal_stress);
  InterfaceFields f;
  f.x1.resize(nx);
  for (int i = 0; i < nx; ++i)
    f.x1[i] = params.geometry.x_min + i * dx;
  f.velocity.assign(nx, 0.0);
  f.half_velocity.assign(nx, 0.0);
  f.slip.assign(nx, 0.0);
  f.opening.assign(nx, 0.0);
  f.shear_traction.assign(nx, params.loading.shear_stress);
  f.pressure.assign(nx, p0);
  f.strength.assign(nx, params.friction.mu * p0);
  f.state.assign(nx, std::int8_t(NodeState::stick));
  return f;
}

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
