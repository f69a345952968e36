// The ill-posedness warning (solver/interface/ill_posedness.hpp).
#include "solver/interface/ill_posedness.hpp"

namespace slipfront {

std::string bimaterial_coulomb_warning(const SimulationParams& params) {
  if (params.friction.law != FrictionLaw::coulomb || !params.lower.elastic()) return "";
  const Material &upper = params.material, &lower = params.lower.material;
  const bool dissimilar = upper.density != lower.density ||
                          upper.young_modulus != lower.young_modulus ||
                          upper.poisson_ratio != lower.poisson_ratio;
  if (!dissimilar) return "";
  // tests/solver/interface_growth_test.cpp: rate dx / c_s 0.074-0.079 (BI)
  return "plain Coulomb friction between two different elastic solids is ill-posed: "
         "steady sliding is unstable at every wavelength, the finest mode of the "
         "mesh growing fastest, at a rate proportional to 1/dx (Adams 1995; Ranjith "
         "& Rice 2001), so the results do not converge under refinement; "
         "prakash_clifton friction regularises it (docs/verification.md)";
}

} // namespace slipfront
