// The ill-posedness warning (solver/interface/ill_posedness.hpp).
#include "solver/interface/ill_posedness.hpp"

#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

#include <sstream>

namespace slipfront {

std::string bimaterial_coulomb_warning(const SimulationParams& params) {
  // Any law without regularisation: plain Coulomb, or slip weakening (which slides at the
  // constant mu_d once it has weakened).
  if (effective_regularization(params.friction) != Regularization::none || !params.lower.elastic())
    return "";
  const Material &upper = params.material, &lower = params.lower.material;
  const bool dissimilar = upper.density != lower.density ||
                          upper.young_modulus != lower.young_modulus ||
                          upper.poisson_ratio != lower.poisson_ratio;
  if (!dissimilar) return "";
  // tests/solver/interface_growth_test.cpp: rate dx / c_s 0.074-0.079 (BI)
  return std::string("friction without regularisation (law ") + to_string(params.friction.law) +
         ") between two different elastic solids is ill-posed: "
         "steady sliding is unstable at every wavelength, the finest mode of the "
         "mesh growing fastest, at a rate proportional to 1/dx (Adams 1995; Ranjith "
         "& Rice 2001), so the results do not converge under refinement; "
         "prakash_clifton friction (or a slip_scale or time_scale regularization) "
         "regularises it (docs/verification.md)";
}

bool coulomb_well_posed(const SimulationParams& params, std::string& why) {
  if (params.friction.law == FrictionLaw::slip_weakening) {
    why = "not judged for slip-weakening friction (weakening makes Coulomb ill-posed at smaller "
          "friction coefficients too)";
    return false;
  }
  const double mu = params.friction.mu;
  if (!params.lower.elastic()) {
    const bool small = mu < 1.0;
    std::ostringstream text;
    text << mu; // six significant digits
    why = "an elastic solid on the rigid plane with mu = " + text.str() +
          (small ? " < 1: well-posed (Renardy 1992)"
                 : " >= 1: ill-posed for equal static and kinetic coefficients (Martins et al. "
                   "1995)");
    return small;
  }
  const Material &upper = params.material, &lower = params.lower.material;
  const bool identical = upper.density == lower.density &&
                         upper.young_modulus == lower.young_modulus &&
                         upper.poisson_ratio == lower.poisson_ratio;
  why = identical ? "two identical elastic solids: slip does not change the normal traction, "
                    "well-posed"
                  : "two different elastic solids: ill-posed (Adams 1995; Ranjith & Rice 2001)";
  return identical;
}

} // namespace slipfront
