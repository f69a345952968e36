#include "solver/spectral/bimaterial_relations.hpp"

#include "solver/spectral/half_space_kernels.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront::spectral {

namespace {

using complex = std::complex<double>;

Matrix2 inverse(const Matrix2& m) {
  const complex det = m.m11 * m.m22 - m.m12 * m.m21;
  return {m.m22 / det, -m.m12 / det, -m.m21 / det, m.m11 / det};
}

} // namespace

Matrix2 half_space_stiffness(complex sigma, const Material& solid, bool lower) {
  const double mu = solid.shear_modulus();
  const ModeStiffness k =
      mode_stiffness(sigma / solid.s_wave_speed(), solid.s_wave_speed() / solid.p_wave_speed());
  const complex i(0.0, 1.0);
  // The lower solid in its mirrored frame (u'_2 = -u_2, sigma'_12 = -sigma_12) is an upper
  // half-space: back in the true frame its diagonal entries change sign.
  const double diagonal = lower ? -1.0 : 1.0;
  return {diagonal * mu * k.k11, i * mu * k.k12, -i * mu * k.k12, diagonal * mu * k.k22};
}

Matrix2 interface_stiffness(complex sigma, const Material& upper, const Material& lower) {
  const Matrix2 a = inverse(half_space_stiffness(sigma, upper, false));
  const Matrix2 b = inverse(half_space_stiffness(sigma, lower, true));
  return inverse({a.m11 - b.m11, a.m12 - b.m12, a.m21 - b.m21, a.m22 - b.m22});
}

double frictionless_normal_stiffness(const Material& solid, double v) {
  const ModeStiffness k = mode_stiffness(complex(0.0, v / solid.s_wave_speed()),
                                         solid.s_wave_speed() / solid.p_wave_speed());
  return (k.k22 - k.k12 * k.k12 / k.k11).real();
}

double generalized_rayleigh_speed(const Material& upper, const Material& lower) {
  const auto f = [&](double v) {
    return upper.shear_modulus() * frictionless_normal_stiffness(upper, v) +
           lower.shear_modulus() * frictionless_normal_stiffness(lower, v);
  };
  // f(0) = -2 (1 - r+^2) mu+ - 2 (1 - r-^2) mu- < 0; a root below the slower shear speed
  // exists if f is positive there (the slower solid's N -> K12^2 / (a Q) > 0).
  double lo = 0.0, hi = std::min(upper.s_wave_speed(), lower.s_wave_speed());
  if (!(f(hi) > 0.0)) return std::numeric_limits<double>::quiet_NaN();
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (f(mid) < 0.0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

} // namespace slipfront::spectral
