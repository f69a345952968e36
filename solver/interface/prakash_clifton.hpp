// The simplified Prakash-Clifton regularisation of the frictional strength (paper eq. 1;
// docs/physics.md "Regularisation"): tau_s follows the Coulomb strength mu max(0, p) with a
// slip-distance lag,
//   d(tau_s)/dt = -(|V| + V*) / L * (tau_s - mu max(0, p)),
// and the three ways of advancing it over a step (params.friction.update).
#pragma once

#include "solver/params.hpp"

namespace slipfront {

const char* to_string(StrengthUpdate update); // the job JSON spelling

// Advances the regularised tau_s over one step dt. The slip speed |V| is that of the step (the
// leapfrog velocity over it); the pressure goes from p_start to p_end. With k = (|V| + V*) / L, c =
// mu max(0, p) and x = k dt:
//   exponential_ramp (default): exact when c varies linearly from c_start to c_end,
//     tau_end = c_end + (tau - c_start) exp(-x) - (c_end - c_start) (1 - exp(-x)) / x;
//     second order in dt, and a convex combination of tau, c_start and c_end (stable).
//   exponential (the reference scheme, docs/physics.md): exact when c stays at c_end over the step,
//     tau_end = c_end + (tau - c_end) exp(-x); first order in dt (the target leads by
//     dt/2), a contraction for every x.
//   explicit_euler (failure studies): tau_end = tau - x (tau - c_end); unstable once x > 2.
double prakash_clifton_strength(const Friction& friction, double strength, double pressure_start,
                                double pressure_end, double slip_speed, double dt);

} // namespace slipfront
