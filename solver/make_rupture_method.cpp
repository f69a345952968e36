#include "solver/make_rupture_method.hpp"

#include "solver/fe_method.hpp"

namespace slipfront {

std::unique_ptr<RuptureMethod> make_rupture_method(const SimulationParams& params) {
  return std::make_unique<FiniteElementMethod>(params);
}

} // namespace slipfront
