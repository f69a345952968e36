// The interface relation of two elastic half-spaces (solver/spectral/bimaterial_relations.hpp,
// docs/spectral-bi.md "Two half-spaces") against its limits:
//   - identical solids: the homogeneous full space, decoupled, with the mode II and mode I
//     kernels derived directly from potentials, (mu/2) (4ab - (2 + p^2)^2) / (p^2 b) and
//     (mu/2) (4ab - (2 + p^2)^2) / (p^2 a), at complex p; static stiffness mu/(2(1 - nu)) and
//     radiation damping eta/2;
//   - any two solids: the static compliances add (the series of the two half-spaces), the
//     radiation dampings combine in series;
//   - a lower solid ever stiffer (E- growing, its nu and rho fixed) gives the rigid plane;
//   - the generalized Rayleigh speed: the Rayleigh speed for identical solids, and for the
//     bimaterial presets' solids the root found independently from a 4x4 potential problem
//     (tests/solver/reference/generalized_rayleigh.py).
#include "verification_support.hpp"

#include "solver/spectral/bimaterial_relations.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>

namespace slipfront {
namespace {

using complex = std::complex<double>;
using spectral::Matrix2;
using verification::measure;

Material from_speeds(double rho, double cp, double cs) {
  const double mu = rho * cs * cs;
  const double nu = (cp * cp - 2 * cs * cs) / (2 * (cp * cp - cs * cs));
  return {rho, 2 * mu * (1 + nu), nu};
}

// The bimaterial presets' solids: upper (more compliant) and lower.
const Material upper_preset = from_speeds(2730.834, 4537.973, 2620.0);
const Material lower_preset = from_speeds(2745.739, 5354.808, 3091.6);

double relative(complex a, complex b) {
  return std::abs(a - b) / std::abs(b);
}

TEST(BimaterialKernels, IdenticalSolidsGiveTheHomogeneousModeTwoAndModeOneKernels) {
  const Material m; // the paper's solid, nu = 0.25
  const double cs = m.s_wave_speed(), r = cs / m.p_wave_speed(), mu = m.shear_modulus();
  double worst = 0, coupling = 0;
  // (Not at |p| << 1, where the closed form itself loses digits to the cancellation in
  // 4ab - (2 + p^2)^2 = O(p^2): the static limit is the next test.)
  for (complex p : {complex(0.05, 0), complex(0.3, 0), complex(2, 0), complex(40, 0),
                    complex(0.5, 0.7), complex(0.1, 1.4), complex(1e-4, 0.6), complex(3, -2)}) {
    const Matrix2 kc = spectral::interface_stiffness(p * cs, m, m);
    const complex a = std::sqrt(1.0 + r * r * p * p), b = std::sqrt(1.0 + p * p);
    const complex rayleigh = 4.0 * a * b - (2.0 + p * p) * (2.0 + p * p);
    const complex mode_two = 0.5 * mu * rayleigh / (p * p * b);
    const complex mode_one = 0.5 * mu * rayleigh / (p * p * a);
    worst = std::max({worst, relative(kc.m11, mode_two), relative(kc.m22, mode_one)});
    coupling = std::max(
        {coupling, std::abs(kc.m12) / std::abs(kc.m11), std::abs(kc.m21) / std::abs(kc.m11)});
  }
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(coupling, 1e-13);
  measure("bimaterial kernels, identical solids vs full-space mode II / mode I at 8 complex p: "
          "max rel. error %.1e, coupling %.1e",
          worst, coupling);
}

TEST(BimaterialKernels, StaticStiffnessAndRadiationDampingOfIdenticalSolids) {
  const Material m;
  const double cs = m.s_wave_speed(), mu = m.shear_modulus(), nu = m.poisson_ratio;
  const Matrix2 statics = spectral::interface_stiffness(1e-9 * cs, m, m);
  EXPECT_NEAR(statics.m11.real(), -mu / (2 * (1 - nu)), 1e-12);
  EXPECT_NEAR(statics.m22.real(), -mu / (2 * (1 - nu)), 1e-12);
  // p -> infinity: S = |k| Kc D = -(eta / 2) V with V = s D, so Kc -> -(eta / 2) sigma.
  const double sigma = 1e7 * cs;
  const Matrix2 fast = spectral::interface_stiffness(sigma, m, m);
  const double eta1 = m.density * cs, eta2 = m.density * m.p_wave_speed();
  const double e1 = std::abs(-fast.m11.real() / sigma / (0.5 * eta1) - 1);
  const double e2 = std::abs(-fast.m22.real() / sigma / (0.5 * eta2) - 1);
  EXPECT_LT(e1, 1e-6);
  EXPECT_LT(e2, 1e-6);
  measure("bimaterial kernels, identical solids: static %.15g (mu/(2(1-nu)) = %.15g), "
          "radiation damping / (eta/2) - 1: %.1e, %.1e",
          -statics.m11.real(), mu / (2 * (1 - nu)), e1, e2);
}

TEST(BimaterialKernels, TwoSolidsAddTheirStaticCompliancesAndCombineTheirDampingsInSeries) {
  const Material &a = upper_preset, &b = lower_preset;
  // Slip at no normal-traction change: D1 / S1 = -(1/|k|) ((1 - nu+)/mu+ + (1 - nu-)/mu-),
  // the same for opening at no shear-traction change (-M(0)^-1 = [[1 - nu, .], [., 1 - nu]]).
  const Matrix2 kc = spectral::interface_stiffness(1e-9 * a.s_wave_speed(), a, b);
  const double det = (kc.m11 * kc.m22 - kc.m12 * kc.m21).real();
  const double compliance =
      (1 - a.poisson_ratio) / a.shear_modulus() + (1 - b.poisson_ratio) / b.shear_modulus();
  const double slip = kc.m22.real() / det, opening = kc.m11.real() / det; // (Kc^-1)_11, _22
  EXPECT_LT(std::abs(-slip / compliance - 1), 1e-12);
  EXPECT_LT(std::abs(-opening / compliance - 1), 1e-12);
  const double sigma = 1e8 * a.s_wave_speed();
  const Matrix2 fast = spectral::interface_stiffness(sigma, a, b);
  const double ea = a.density * a.s_wave_speed(), eb = b.density * b.s_wave_speed();
  const double pa = a.density * a.p_wave_speed(), pb = b.density * b.p_wave_speed();
  EXPECT_LT(std::abs(-fast.m11.real() / sigma / (ea * eb / (ea + eb)) - 1), 1e-6);
  EXPECT_LT(std::abs(-fast.m22.real() / sigma / (pa * pb / (pa + pb)) - 1), 1e-6);
  measure("bimaterial kernels, preset solids: static slip compliance %.6e (sum %.6e), "
          "opening %.6e",
          -slip, compliance, -opening);
}

TEST(BimaterialKernels, AStifferAndStifferLowerSolidGivesTheRigidPlane) {
  const Material& upper = upper_preset;
  const double cs = upper.s_wave_speed();
  double previous = 0;
  for (double factor : {1e2, 1e4, 1e6, 1e8}) {
    Material lower = lower_preset;
    lower.young_modulus *= factor; // nu and rho fixed: the wave speeds' ratio stays
    double worst = 0;
    for (complex p : {complex(1e-6, 0), complex(0.4, 0.3), complex(0.2, 0.95), complex(5, 0)}) {
      const Matrix2 kc = spectral::interface_stiffness(p * cs, upper, lower);
      const Matrix2 rigid = spectral::half_space_stiffness(p * cs, upper, false);
      worst = std::max({worst, relative(kc.m11, rigid.m11), relative(kc.m22, rigid.m22),
                        relative(kc.m12, rigid.m12)});
    }
    measure("bimaterial kernels: E- x %.0e, max rel. difference from the rigid plane %.2e", factor,
            worst);
    // The lower side's compliance is mu+/mu- of the upper's: the difference falls like 1/E-.
    if (previous > 0) {
      EXPECT_LT(worst, 0.02 * previous) << "E- x " << factor;
    }
    previous = worst;
  }
  EXPECT_LT(previous, 1e-6);
}

TEST(BimaterialKernels, GeneralizedRayleighSpeed) {
  const Material m;
  const double identical = spectral::generalized_rayleigh_speed(m, m) / m.s_wave_speed();
  EXPECT_NEAR(identical, 0.9194016867619661, 1e-13); // sqrt(2 - 2/sqrt(3))
  // tests/solver/reference/generalized_rayleigh.py: 2569.7129430099070777 m/s.
  const double c_gr = spectral::generalized_rayleigh_speed(upper_preset, lower_preset);
  EXPECT_NEAR(c_gr, 2569.7129430099070777, 1e-8);
  EXPECT_NEAR(spectral::generalized_rayleigh_speed(lower_preset, upper_preset), c_gr, 1e-8);
  // A strong contrast has none (Weertman 1980: it exists for moderate contrasts only).
  Material stiff = m;
  stiff.young_modulus *= 100;
  EXPECT_TRUE(std::isnan(spectral::generalized_rayleigh_speed(m, stiff)));
  measure("generalized Rayleigh speed: identical solids %.15f c_s; preset solids %.10f m/s "
          "(c_s upper 2620, lower 3091.6)",
          identical, c_gr);
}

} // namespace
} // namespace slipfront
