// The elastodynamic relation of the interface between two elastic half-spaces, one Fourier
// mode at a time, from the kernels of each (half_space_kernels.hpp); docs/spectral-bi.md
// "Two half-spaces" derives it. For tests, documentation and the generalized Rayleigh speed;
// the time stepping (spectral_method.hpp) uses the half-spaces separately.
//
// Upper solid x2 > 0, lower x2 < 0, the traction sigma_2j = S_j e^{i k x1} continuous across
// the interface, D_j = u_j(upper) - u_j(lower) the relative motion (slip, opening). For k > 0
// and the Laplace variable s, with sigma = s / |k| [m/s] and p = sigma / c_s of each solid:
//     upper:  S = mu+ |k| K+(p+) D+,   K = [[K11, i K12], [-i K12, K22]]
//     lower:  S = mu- |k| K-(p-) D-,   K- = [[-K11, i K12], [-i K12, -K22]]  (mirrored frame)
//     D = D+ - D- = (1/|k|) [K+^-1/mu+ - K-^-1/mu-] S  =: (1/|k|) Kc^-1 S.
#pragma once

#include "solver/params.hpp"

#include <complex>

namespace slipfront::spectral {

// A 2x2 complex matrix [[m11, m12], [m21, m22]].
struct Matrix2 {
  std::complex<double> m11, m12, m21, m22;
};

// mu K(p) of one half-space in the true frame: upper (x2 > 0) or lower (x2 < 0), at
// sigma = s / |k| (k > 0): S = |k| (mu K) D.
Matrix2 half_space_stiffness(std::complex<double> sigma, const Material& solid, bool lower);

// Kc: S = |k| Kc D for the relative motion D of two bonded-by-traction half-spaces.
Matrix2 interface_stiffness(std::complex<double> sigma, const Material& upper,
                            const Material& lower);

// N(v) = K22 - K12^2 / K11 at p = i v / c_s: a half-space's normal stiffness (per mu |k|)
// with no shear traction, for a wave travelling at v < c_s along its surface.
double frictionless_normal_stiffness(const Material& solid, double v);

// The generalized Rayleigh speed (Weertman 1980): the root v in (0, min c_s) of
// mu+ N+(v) + mu- N-(v) = 0, the speed of a wave that slides the interface without opening
// and without shear traction. NaN if the pair of materials has none.
double generalized_rayleigh_speed(const Material& upper, const Material& lower);

} // namespace slipfront::spectral
