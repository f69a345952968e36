// Nucleation (docs/physics.md "Nucleation"): the moving ellipse of the paper's appendix A
// (after Cochard & Rice 2000, appendix B), or an overstressed patch (a prestress, set up in
// interface_parameters.hpp), or the smooth stress perturbation of SCEC TPV101, or none.
//
// The ellipse: with xi = (x1 - v t)/a, eta = (x1 + v t)/b - eta0, eta0 = sqrt(a^2 + b^2)/b, inside
// the ellipse 1 - xi^2 - eta^2 > 0 the normal load is reduced by alpha |tau2_0| (1 - xi^2 -
// eta^2)^2: a tensile traction of that size acts on the solid at the interface.
#pragma once

#include "solver/params.hpp"

namespace slipfront {

// Tensile traction [Pa] (>= 0, pulling the solid off the plane) of the ellipse at (x1, t),
// normal_stress the node's tau2_0; 0 for any other nucleation.
double nucleation_traction(const Nucleation& nucleation, double normal_stress, double x1, double t);

// The shear traction [Pa] the stress perturbation adds at (x1, t), in the direction of a
// positive initial shear stress (SCEC TPV101: Delta tau_0 F(r) G(t)); 0 for any other
// nucleation.
double nucleation_shear_traction(const Nucleation& nucleation, double x1, double t);

// The nucleation patch: the x1 interval the ellipse covers over all t >= 0, the
// overstressed patch [x1_min, x1_max], or the perturbation's [x1 - R, x1 + R]; empty
// (lo > hi) without nucleation.
struct Interval {
  double lo, hi;
};
Interval nucleation_patch(const Nucleation& nucleation);

// The last time at which the nucleation acts: the ellipse's end, the perturbation's rise
// time (it stays, constant, after it); 0 for the overstressed patch (a prestress, there from
// the start) and without nucleation.
double nucleation_end_time(const Nucleation& nucleation);

} // namespace slipfront
