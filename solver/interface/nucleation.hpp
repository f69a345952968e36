// Nucleation of the paper's appendix A (after Cochard & Rice 2000, appendix B).
//
// With xi = (x1 - v t)/a, eta = (x1 + v t)/b - eta0, eta0 = sqrt(a^2 + b^2)/b, inside the
// ellipse 1 - xi^2 - eta^2 > 0 the normal load is reduced by alpha |tau2_0| (1 - xi^2 -
// eta^2)^2: a tensile traction of that size acts on the solid at the interface.
#pragma once

#include "solver/params.hpp"

namespace slipfront {

// Tensile traction [Pa] (>= 0, pulling the solid off the plane) at (x1, t).
double nucleation_traction(const Nucleation& nucleation, double normal_stress, double x1, double t);

// The x1 interval the ellipse covers over all t >= 0 (the nucleation patch).
struct Interval {
  double lo, hi;
};
Interval nucleation_patch(const Nucleation& nucleation);

// Last time at which the ellipse is active anywhere.
double nucleation_end_time(const Nucleation& nucleation);

} // namespace slipfront
