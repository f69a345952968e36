// Unilateral contact with the rigid plane and friction, for one interface node and one
// time step (docs/physics.md "The step at an interface node"), shared by the rupture methods:
//   1. the caller gives the trial motion, from every force except contact and friction:
//      the velocities v1_trial, v2_trial of the next half step;
//   2. normal: the reaction that makes the next normal displacement exactly zero; if it is
//      compressive the node is in contact with p = reaction/dx, otherwise open with p = 0;
//   3. strength: the node's friction state advanced from the last step to this one with the
//      slip speed of that interval (given by the caller) and the pressure going from the
//      last step's p to this step's (default) or frozen at this step's (the reference
//      scheme of docs/physics.md), see friction/strength_law.hpp;
//   4. tangential: the force that makes the next tangential velocity zero; if its size is
//      at most tau_s dx the node sticks, otherwise it slips with tau_s dx opposing the trial
//      slip direction. An open node carries no traction.
// A force F on the node changes its velocity by dt F / mass_j along x_j. The finite
// elements pass the lumped node mass for both directions; the spectral boundary-integral
// method passes mass_j = eta_j dx dt with the radiation damping eta_1 = rho c_s,
// eta_2 = rho c_p (its traction-velocity relation tau_j = tau_j^trial - eta_j v_j).
#pragma once

#include "solver/interface/friction/strength_law.hpp"
#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"

namespace slipfront {

struct InterfaceNodeConstants {
  double mass1 = 0, mass2 = 0; // mass seen by the law along x1 and x2 [kg/m] (FE: both the
                               // lumped node mass)
  double dt = 0;
  double tributary_length = 0; // dx
  StrengthLaw law;             // the friction law (its values are the node's)
};

struct InterfaceNodeStep {
  double contact_force1 = 0; // force of the plane on the solid, along x1 [N/m]
  double contact_force2 = 0; // along x2 (>= 0: the plane pushes)
  double pressure = 0;       // p [Pa]
  double strength = 0;       // tau_s after the step [Pa]
  FrictionState friction;    // the node's friction state after the step
  NodeState state = NodeState::stick;
  double v1 = 0, v2 = 0; // velocity of the next half step (exactly 0 when held by the plane)
};

// friction: the node's friction values; u2: normal displacement now (>= 0); v1_trial,
// v2_trial: velocities of the next half step without the plane's force; slip_speed: |V|
// over the last interval (enters the strength update); state, previous_pressure: the
// node's friction state and p of the last step.
InterfaceNodeStep resolve_interface_node(const InterfaceNodeConstants& c,
                                         const FrictionValues& friction, double u2, double v1_trial,
                                         double v2_trial, double slip_speed,
                                         const FrictionState& state, double previous_pressure);

} // namespace slipfront
