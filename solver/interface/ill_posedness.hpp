// What a run says when its interface problem is ill-posed: friction without regularisation
// between two different elastic solids (Adams 1995; Ranjith & Rice 2001; docs/physics.md "Two
// solids"), for both methods; and whether a scene is well-posed without its regularisation,
// which each coefficient law judges (coefficient_law.hpp) from the judgements shared here.
#pragma once

#include "solver/params.hpp"

#include <string>

namespace slipfront {

// The warning for friction without regularisation between two solids of different
// materials; empty for every other scene (the rigid plane, identical solids, a regularised
// law: prakash_clifton, or a slip_scale or time_scale regularization).
std::string bimaterial_coulomb_warning(const SimulationParams& params);

// Whether the scene without its regularisation (the job's coefficient law alone) is a
// well-posed problem whose mesh-converged answer the regularised runs may be compared with
// (docs/studies-api.md "L search"); the law says (its well_posed_unregularized), `why` says
// which and why.
bool coulomb_well_posed(const SimulationParams& params, std::string& why);

// Two elastic solids without regularisation of the normal stress: identical ones are
// well-posed (slip does not change the normal traction), different ones are not (Adams 1995;
// Ranjith & Rice 2001). `why` says which.
bool two_solids_well_posed(const SimulationParams& params, std::string& why);

} // namespace slipfront
