// What a run says when its interface problem is ill-posed: plain Coulomb friction between two
// different elastic solids (Adams 1995; Ranjith & Rice 2001; docs/physics.md "Two solids"),
// for both methods.
#pragma once

#include "solver/params.hpp"

#include <string>

namespace slipfront {

// The warning for plain Coulomb friction between two solids of different materials; empty
// for every other scene (the rigid plane, identical solids, Prakash-Clifton friction).
std::string bimaterial_coulomb_warning(const SimulationParams& params);

} // namespace slipfront
