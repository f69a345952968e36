// Unilateral contact with the rigid plane and friction, for one interface node and one
// central-difference step (the scheme of SPEC §1):
//   1. the trial motion from every force except contact and friction;
//   2. normal: the reaction that makes the next normal displacement exactly zero; if it is
//      compressive the node is in contact with p = reaction/dx, otherwise open with p = 0;
//   3. strength: tau_s advanced from the last step to this one with the slip speed of that
//      interval (the previous half step's |V|) and the pressure going from the last step's
//      p to this step's (default) or frozen at this step's (SPEC §1), see friction.hpp;
//   4. tangential: the force that makes the next tangential velocity zero; if its size is
//      at most tau_s dx the node sticks, otherwise it slips with tau_s dx opposing the trial
//      slip direction. An open node carries no traction.
#pragma once

#include "solver/interface_fields.hpp"
#include "solver/params.hpp"

namespace slipfront {

struct InterfaceNodeConstants {
  double mass = 0; // lumped mass of the node [kg/m]
  double dt = 0;
  double tributary_length = 0; // dx
  Friction friction;
};

struct InterfaceNodeStep {
  double contact_force1 = 0; // force of the plane on the solid, along x1 [N/m]
  double contact_force2 = 0; // along x2 (>= 0: the plane pushes)
  double pressure = 0;       // p [Pa]
  double strength = 0;       // tau_s after the step [Pa]
  NodeState state = NodeState::stick;
  double v1 = 0, v2 = 0; // velocity of the next half step (exactly 0 when held by the plane)
};

// u2: normal displacement now (>= 0); v1, v2: velocity of the previous half step;
// f1, f2: every force on the node except the contact force of the plane.
// `strength` and `previous_pressure` are the node's tau_s and p of the last step.
InterfaceNodeStep resolve_interface_node(const InterfaceNodeConstants& c, double u2, double v1,
                                         double v2, double f1, double f2, double strength,
                                         double previous_pressure);

} // namespace slipfront
