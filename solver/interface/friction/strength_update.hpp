// The three ways of advancing the regularisation ODE dc*/dt = -k (c* - c) over one step dt
// with x = k dt (params.friction.update; docs/physics.md "Strength update"), shared by the
// slip-scale and the time-scale regularisations:
//   exponential_ramp (default): exact when k is frozen and c varies linearly from c_start to
//     c_end over the step,
//       c*_end = c_end + (c* - c_start) exp(-x) - (c_end - c_start) (1 - exp(-x)) / x;
//     second order in dt, and a convex combination of c*, c_start and c_end (stable).
//   exponential (the reference scheme, docs/physics.md): exact when c stays at c_end,
//       c*_end = c_end + (c* - c_end) exp(-x);
//     first order in dt (the target leads by dt/2), a contraction for every x.
//   explicit_euler (failure studies): c*_end = c* - x (c* - c_end); unstable once x > 2.
#pragma once

#include "solver/interface/friction/law_description.hpp"
#include "solver/params.hpp"

namespace slipfront {

const char* to_string(StrengthUpdate update); // the job JSON spelling

// `strength_update`, the choice of the regularisations that filter (slip and time scale).
LawChoice strength_update_choice();

double filtered_strength(StrengthUpdate update, double filtered, double c_start, double c_end,
                         double x);

} // namespace slipfront
