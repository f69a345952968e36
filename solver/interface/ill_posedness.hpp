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

// Whether the scene under plain Coulomb friction (its constant mu, no regularisation) is a
// well-posed problem whose mesh-converged answer the regularised runs may be compared with
// (docs/studies-api.md "L search"): on the rigid plane when mu < 1 (Renardy 1992; Martins et
// al. 1995: ill-posed only when the static and kinetic coefficients are equal and above one),
// between two identical solids (no slip-normal coupling); not between two different solids
// (Adams 1995), and not judged for slip weakening (weakening friction is ill-posed at smaller
// mu as well, paper Sec. 1). `why` says which.
bool coulomb_well_posed(const SimulationParams& params, std::string& why);

} // namespace slipfront
