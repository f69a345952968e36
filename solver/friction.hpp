// The frictional strength tau_s and its evolution (paper eq. 1, SPEC §1):
//   d(tau_s)/dt = -(|V| + V*) / L * (tau_s - mu max(0, p))      (simplified Prakash-Clifton)
//   tau_s = mu max(0, p)                                         (Coulomb)
#pragma once

#include "solver/params.hpp"

namespace slipfront {

// Advance tau_s over one step dt with the pressure p and slip speed |V| frozen over the
// step. The exponential update is the exact solution for frozen coefficients:
//   tau_s(t+dt) = mu p + (tau_s(t) - mu p) exp(-dt (|V| + V*) / L),
// a contraction for every L (stable). Explicit Euler, offered for failure studies, is
//   tau_s(t+dt) = tau_s(t) - dt (|V| + V*) / L (tau_s(t) - mu p),
// unstable once dt (|V| + V*) / L > 2.
double advance_strength(const Friction& friction, double strength, double pressure,
                        double slip_speed, double dt);

} // namespace slipfront
