// Builds the rupture method a job asks for (today always the finite elements).
#pragma once

#include "solver/params.hpp"
#include "solver/rupture_method.hpp"

#include <memory>

namespace slipfront {

std::unique_ptr<RuptureMethod> make_rupture_method(const SimulationParams& params);

} // namespace slipfront
