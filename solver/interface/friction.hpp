// The frictional strength tau_s of the law a job chose (params.friction.law), advanced over
// one step; each law in a file of its own beside this one:
//   coulomb          tau_s = mu max(0, p) at every instant;
//   prakash_clifton  the regularised strength of paper eq. 1 (prakash_clifton.hpp).
// The interface law (interface_law.hpp) asks for the strength here and nowhere else, so a
// new law is a value of FrictionLaw (params.hpp), its file here and its case in
// advance_strength (docs/physics.md "Friction").
#pragma once

#include "solver/params.hpp"

namespace slipfront {

// tau_s after one step dt from `strength` before it: the pressure goes from pressure_start
// to pressure_end over the step, slip_speed is |V| over it (how each law uses them: its
// file).
double advance_strength(const Friction& friction, double strength, double pressure_start,
                        double pressure_end, double slip_speed, double dt);

} // namespace slipfront
