// Contact and friction between two deformable solids at one pair of interface nodes, the
// split-node (traction-at-split-node) method of Andrews (1999) and Day et al. (2005), in
// one time step (docs/physics.md "Two solids").
//
// Each side offers, per direction j, a mass m_j (FE: its lumped node mass; BI: eta_j dx dt)
// and a trial velocity v_j of the next half step from every force but the interface's, in
// the true frame (x2 up, the upper solid above). The interface force C acts on the upper
// node as +C and on the lower node as -C:
//     v+ = v+_trial + dt C / m+,     v- = v-_trial - dt C / m-,
// so the relative motion (upper minus lower) obeys the single-node law of interface_law.hpp
// with the effective mass m+ m- / (m+ + m-) on the gap and the relative trial velocity. The
// law's answer is then shared between the sides so that momentum is kept, and what it holds
// is held exactly: a stuck pair moves with one tangential velocity, the centre-of-mass
// velocity (m+ v+_trial + m- v-_trial) / (m+ + m-).
//
// A rigid lower side (the paper's plane) is the single-node law itself, bit for bit.
#pragma once

#include "solver/interface/interface_law.hpp"

namespace slipfront {

// One side of a node pair: masses along x1 and x2 and trial velocities (true frame).
struct InterfaceSide {
  double mass1 = 0, mass2 = 0; // [kg/m]
  double v1 = 0, v2 = 0;       // trial velocities of the next half step [m/s]
};

// A pair of forces within the node pair, +F on the upper side and -F on the lower, that the
// trial velocities leave out (FE: the initial contact force C0 of the perturbation
// formulation, docs/physics.md "Two solids"). The law sees it; the sides' velocities only
// C - F, so that a pair the interface keeps still stays exactly at rest.
struct PairForce {
  double f1 = 0, f2 = 0; // [N/m]
};

struct SplitNodeStep {
  // The interface force C on the upper side (contact_force1/2), p, strength and state; its
  // v1, v2 are the relative velocities (upper minus lower) of the next half step.
  InterfaceNodeStep relative;
  InterfaceSide upper, lower; // the masses as given, the velocities of the next half step
};

// `c`: dt, dx and the friction law (its masses are not used); gap: u2(upper) - u2(lower) now
// (>= 0); slip_speed, strength, previous_pressure as for resolve_interface_node; `internal`:
// the pair force the trial velocities leave out. With `lower_rigid` the lower side and
// `internal` are ignored (zero motion, infinite mass: the plane takes any force, so the upper
// trial velocity holds every force but the plane's, as for resolve_interface_node).
SplitNodeStep resolve_split_node(const InterfaceNodeConstants& c, double gap,
                                 const InterfaceSide& upper, const InterfaceSide& lower,
                                 bool lower_rigid, double slip_speed, double strength,
                                 double previous_pressure, const PairForce& internal = {});

} // namespace slipfront
