// Builds the rupture method a job asks for (params.method): the finite elements or the
// spectral boundary-integral method.
#pragma once

#include "solver/params.hpp"
#include "solver/rupture_method.hpp"

#include <memory>

namespace slipfront {

std::unique_ptr<RuptureMethod> make_rupture_method(const SimulationParams& params);

} // namespace slipfront
