// What a run says when its interface problem is ill-posed: friction without regularisation
// (plain Coulomb, slip weakening) between two different elastic solids (Adams 1995; Ranjith & Rice
// 2001; docs/physics.md "Two solids"), for both methods.
#pragma once

#include "solver/params.hpp"

#include <string>

namespace slipfront {

// The warning for friction without regularisation between two solids of different
// materials; empty for every other scene (the rigid plane, identical solids, a regularised
// law: prakash_clifton, or a slip_scale or time_scale regularization).
std::string bimaterial_coulomb_warning(const SimulationParams& params);

} // namespace slipfront
