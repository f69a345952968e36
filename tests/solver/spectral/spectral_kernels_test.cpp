// Case 16: the half-space kernels of the spectral boundary-integral method
// (solver/spectral/half_space_kernels.hpp) against
//   - an independent derivation and numerical inverse Laplace transform (mpmath Talbot,
//     de Hoog and an imaginary-axis integral agreeing to 1e-36; tests/solver/reference/,
//     values in tests/solver/data/half_space_kernels_reference.json),
//   - their known limits: static half-space (Flamant), instantaneous response, radiation
//     damping, the Rayleigh root of the traction-free surface, decay of the memory tail.
#include "verification_support.hpp"

#include "solver/spectral/half_space_kernels.hpp"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <numbers>

namespace slipfront::spectral {
namespace {

using verification::measure;

double r_of_nu(double nu) {
  return std::sqrt((1 - 2 * nu) / (2 * (1 - nu)));
}

nlohmann::json reference() {
  std::ifstream in(SLIPFRONT_TEST_DATA_DIR "/half_space_kernels_reference.json");
  EXPECT_TRUE(in.good()) << "missing reference file";
  return nlohmann::json::parse(in);
}

TEST(HalfSpaceKernels, MatchTheIndependentNumericalInverseLaplaceTransform) {
  const nlohmann::json ref = reference();
  double worst_exact = 0, worst_table = 0;
  for (const auto& [name, nu] : {std::pair{"nu=0.25", 0.25}, std::pair{"nu=0.35", 0.35}}) {
    const nlohmann::json& tables = ref["results"][name]["tables"];
    const HalfSpaceKernels k(r_of_nu(nu), 45.0);
    for (const auto& T_json : ref["T"]) {
      const double T = T_json.get<double>();
      const std::string key = T_json.dump();
      const KernelValues e = k.exact(T), t = k(T);
      const double want[6] = {tables["G11"][key], tables["G22"][key], tables["G12_over_i"][key],
                              tables["H11"][key], tables["H22"][key], tables["H12_over_i"][key]};
      const double got[6] = {e.g11, e.g22, e.g12, e.h11, e.h22, e.h12};
      const double table[3] = {t.g11, t.g22, t.g12};
      for (int j = 0; j < 6; ++j) {
        EXPECT_NEAR(got[j], want[j], 1e-11) << name << " T=" << T << " kernel " << j;
        worst_exact = std::max(worst_exact, std::abs(got[j] - want[j]));
      }
      for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(table[j], want[j], 1e-8) << name << " T=" << T << " table " << j;
        worst_table = std::max(worst_table, std::abs(table[j] - want[j]));
      }
    }
  }
  measure("BI kernels vs independent inverse Laplace (nu 0.25, 0.35; 9 T each): quadrature "
          "max |err| %.2e, interpolated table max |err| %.2e",
          worst_exact, worst_table);
}

TEST(HalfSpaceKernels, StaticLimitIsTheClassicalSinusoidalLoadSolution) {
  // A pressure P cos(k x1) on the half-space with no shear: u2 = (1 - nu) P / (mu k) cos,
  // u1 = -(1 - 2 nu) P / (2 mu k) sin (towards the load): solve S = mu k K(0) D.
  const double nu = 0.25, r = r_of_nu(nu);
  const ModeStiffness k0 = static_stiffness(r);
  const double k11 = k0.k11.real(), k22 = k0.k22.real(), k12 = k0.k12.real();
  // S1 = k11 D1 + i k12 D2 = 0, S2 = -i k12 D1 + k22 D2 = -P (mu k = 1, P = 1).
  const std::complex<double> i(0, 1);
  const std::complex<double> d2 = -1.0 / (k22 - k12 * k12 / k11);
  const std::complex<double> d1 = -i * k12 * d2 / k11;
  EXPECT_NEAR(d2.real(), 1 - nu, 1e-15);
  EXPECT_NEAR(d1.imag(), (1 - 2 * nu) / (2 * (1 - nu)) * (1 - nu), 1e-15); // u1 = -Im(D1) sin
  EXPECT_NEAR(d1.real(), 0.0, 1e-15);
  // The closed form at p -> 0 tends to the static matrix.
  const ModeStiffness small = mode_stiffness({1e-7, 0.0}, r);
  EXPECT_NEAR(small.k11.real(), k11, 1e-12);
  EXPECT_NEAR(small.k12.real(), k12, 1e-12);
}

TEST(HalfSpaceKernels, RadiationDampingAndInstantaneousLimits) {
  for (double nu : {0.25, 0.35}) {
    const double r = r_of_nu(nu);
    const double p = 1e6;
    const ModeStiffness big = mode_stiffness({p, 0.0}, r);
    EXPECT_NEAR(big.k11.real() + p, 0.0, 1e-5);     // -rho c_s V
    EXPECT_NEAR(big.k22.real() + p / r, 0.0, 1e-5); // -rho c_p V
    EXPECT_NEAR(big.k12.real(), 2 - 1 / r, 1e-9);   // instantaneous coupling
    const HalfSpaceKernels k(r, 10.0);
    const KernelValues at0 = k.exact(0.0);
    EXPECT_NEAR(at0.h11, -(2 - r) / (2 * r), 1e-12);
    EXPECT_NEAR(at0.h22, -(2 * r - 1) / (2 * r * r * r), 1e-12);
    EXPECT_NEAR(at0.h12, 0.0, 1e-15);
    EXPECT_NEAR(at0.g11, k.static11(), 1e-15);
    EXPECT_NEAR(at0.g12, k.static12() - k.coupling_at_infinity(), 1e-15);
  }
}

TEST(HalfSpaceKernels, TractionFreeSurfaceHasItsRootAtTheRayleighSpeed) {
  // det K(i w) = K11 K22 - K12^2 = 0 at w = c_R / c_s (0.9194016867619661 for nu = 0.25,
  // = sqrt(2 - 2/sqrt(3)) exactly).
  const double r = r_of_nu(0.25), exact = std::sqrt(2 - 2 / std::sqrt(3.0));
  auto det = [&](double w) {
    const ModeStiffness m = mode_stiffness({0.0, w}, r);
    return (m.k11 * m.k22 - m.k12 * m.k12).real();
  };
  double lo = 0.5, hi = 0.999;
  ASSERT_LT(det(lo) * det(hi), 0.0);
  for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
    const double mid = 0.5 * (lo + hi);
    (det(lo) * det(mid) <= 0 ? hi : lo) = mid;
  }
  EXPECT_NEAR(0.5 * (lo + hi), exact, 1e-13);
  measure("BI kernels: Rayleigh root of det K(i w) = %.15f (exact %.15f)", 0.5 * (lo + hi), exact);
}

TEST(HalfSpaceKernels, MemoryTailDecaysLikeTToTheMinusThreeHalves) {
  // max |g| beyond T = 2 pi q for q = 2, 8, 32: the truncated part of the memory.
  const HalfSpaceKernels k(r_of_nu(0.25), 2 * std::numbers::pi * 64 + 10);
  double previous = 0;
  for (double q : {2.0, 8.0, 32.0}) {
    double tail = 0;
    const double T0 = 2 * std::numbers::pi * q;
    for (double T = T0; T < T0 + 20.0; T += 0.01) {
      const KernelValues v = k(T);
      tail = std::max({tail, std::abs(v.g11), std::abs(v.g22), std::abs(v.g12)});
    }
    if (previous > 0) {
      const double rate = std::log(previous / tail) / std::log(4.0);
      EXPECT_GT(rate, 1.3) << "q = " << q;
      EXPECT_LT(rate, 1.7) << "q = " << q;
    }
    measure("BI kernels: max |g| on [2 pi q, 2 pi q + 20] for q = %g: %.3e", q, tail);
    previous = tail;
  }
}

} // namespace
} // namespace slipfront::spectral
