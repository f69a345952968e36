// The ill-posedness warning and judgements (solver/interface/ill_posedness.hpp).
#include "solver/interface/ill_posedness.hpp"

#include "solver/interface/friction/regularization_law.hpp"

namespace slipfront {

namespace {

bool identical_solids(const SimulationParams& params) {
  const Material &upper = params.material, &lower = params.lower.material;
  return upper.density == lower.density && upper.young_modulus == lower.young_modulus &&
         upper.poisson_ratio == lower.poisson_ratio;
}

} // namespace

std::string bimaterial_coulomb_warning(const SimulationParams& params) {
  // Any law without regularisation: plain Coulomb, or slip weakening (which slides at the
  // constant mu_d once it has weakened).
  if (effective_regularization(params.friction).filters() || !params.lower.elastic()) return "";
  if (identical_solids(params)) return "";
  // tests/solver/interface_growth_test.cpp: rate dx / c_s 0.074-0.079 (BI)
  return "friction without regularisation (law " + params.friction.law +
         ") between two different elastic solids is ill-posed: "
         "steady sliding is unstable at every wavelength, the finest mode of the "
         "mesh growing fastest, at a rate proportional to 1/dx (Adams 1995; Ranjith "
         "& Rice 2001), so the results do not converge under refinement; "
         "prakash_clifton friction (or a slip_scale or time_scale regularization) "
         "regularises it (docs/verification.md)";
}

bool coulomb_well_posed(const SimulationParams& params, std::string& why) {
  return coefficient_law(params.friction).well_posed_unregularized(params, why);
}

bool two_solids_well_posed(const SimulationParams& params, std::string& why) {
  const bool identical = identical_solids(params);
  why = identical ? "two identical elastic solids: slip does not change the normal traction, "
                    "well-posed"
                  : "two different elastic solids: ill-posed (Adams 1995; Ranjith & Rice 2001)";
  return identical;
}

} // namespace slipfront
