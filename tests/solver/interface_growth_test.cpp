// Growth of a perturbation of steady sliding (docs/verification.md, case "interface growth").
//
// A narrow periodic strip (1 m wide; FE: 1 m high with the absorbing top) slides steadily:
// the shear load exceeds mu p by 5 mPa, so the interface slides at V0 = 5 mPa / (rho c_s) =
// 5 mm/s (the slip velocities of the paper's ruptures) and stays uniform in x1 exactly. A
// small random shear traction (zero mean, 1e-6 of the excess load, a fixed seed) acts on the
// interface nodes for 0.02 s; the non-uniform part of the slip velocity,
//   A(t) = rms_i (V_i - mean V),
// is then followed until it reaches 1e-2 V0 (still linear: every node keeps sliding) or the
// run ends, and its exponential growth rate is the least-squares slope of log A(t) over the
// second half of that time. The continuum (an elastic half-space on a rigid plane) has no
// growing mode at this scale; a discrete scheme that has one shows a rate that scales as
// c_s / dx, i.e. a dimensionless rate rate dx / c_s about constant under refinement.
#include "verification_support.hpp"

#include "solver/methods.hpp"
#include "solver/run/periodic_line.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace slipfront {
namespace {

using verification::measure;

constexpr double kExcess = 0.005; // shear load above mu p [Pa]

struct Growth {
  double rate = 0;      // [1/s]
  double scaled = 0;    // rate dx / c_s
  double a_start = 0;   // A at the end of the perturbation, relative to V0
  double a_end = 0;     // A at the end of the fit, relative to V0
  double fit_begin = 0; // [s]
  double fit_end = 0;   // [s]
  double mean_v = 0;    // mean V at the end, relative to V0
  bool finite = true;
};

SimulationParams strip(Method method, double n_d) {
  SimulationParams p = verification::small_block(1.0, 1.0, n_d);
  p.method = method;
  p.top = TopBoundary::absorbing;
  p.loading.shear_stress = p.friction.mu * std::abs(p.loading.normal_stress) + kExcess;
  return p;
}

Growth growth_rate(SimulationParams p, double t_end = 6.0) {
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  const int n = int(std::lround(p.geometry.width / dx));
  const double cs = p.material.s_wave_speed();
  const double v0 = kExcess / (p.material.density * cs);
  const double t_on = 0.2, t_off = 0.22;
  std::vector<double> pattern(n);
  std::mt19937_64 rng(2014);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  double mean = 0;
  for (double& x : pattern)
    mean += (x = uniform(rng)) / n;
  for (double& x : pattern)
    x = 1e-6 * kExcess * (x - mean);
  p.extra_load = [=](double x1, double t) {
    InterfaceTraction load;
    if (t >= t_on && t < t_off) {
      const long i = std::lround((x1 - p.geometry.x_min) / dx);
      load.t1 = pattern[std::size_t(periodic_index(i, n))];
    }
    return load;
  };
  auto method = method_entry(p.method).make(p);
  std::vector<double> ts, logs;
  Growth g;
  double mean_v = 0;
  for (long step = 0;; ++step) {
    method->step(false);
    const InterfaceFields& f = method->interface();
    const double t = double(step) * method->dt(); // t_n of the interface fields
    mean_v = 0;
    for (double v : f.velocity)
      mean_v += v / double(f.velocity.size());
    double sq = 0;
    for (double v : f.velocity)
      sq += (v - mean_v) * (v - mean_v);
    const double a = std::sqrt(sq / double(f.velocity.size()));
    if (!std::isfinite(a)) {
      g.finite = false;
      break;
    }
    if (t >= t_off) {
      if (ts.empty()) g.a_start = a / v0;
      ts.push_back(t);
      logs.push_back(std::log(a / v0));
      if (a > 1e-2 * v0 || t >= t_end) break;
    }
  }
  g.mean_v = mean_v / v0;
  // Least-squares slope over the second half of the recorded time.
  const double t_mid = 0.5 * (ts.front() + ts.back());
  double st = 0, sl = 0, stt = 0, stl = 0;
  int m = 0;
  for (std::size_t k = 0; k < ts.size(); ++k)
    if (ts[k] >= t_mid) {
      st += ts[k];
      sl += logs[k];
      stt += ts[k] * ts[k];
      stl += ts[k] * logs[k];
      ++m;
    }
  g.rate = (m * stl - st * sl) / (m * stt - st * st);
  g.scaled = g.rate * dx / cs;
  g.a_end = std::exp(logs.back());
  g.fit_begin = t_mid;
  g.fit_end = ts.back();
  return g;
}

void print(const char* scheme, double n_d, const Growth& g) {
  measure("interface growth: %s n_d = %g: rate %.4g /s, rate dx/c_s = %.4f (A/V0 %.2e -> %.2e, "
          "fit t in [%.3g, %.3g] s, mean V/V0 %.3f)",
          scheme, n_d, g.rate, g.scaled, g.a_start, g.a_end, g.fit_begin, g.fit_end, g.mean_v);
}

// Below the strip, a second elastic half-space with the contrast of the bimaterial presets
// (the same nu = 0.25, density x 1.00546, c_s x 1.18): the upper solid is the more
// compliant one.
SimulationParams on_lower_solid(SimulationParams p) {
  const double density = 2745.739 / 2730.834, shear_speed = 3091.6 / 2620.0;
  p.lower.side = LowerSide::elastic;
  p.lower.material = p.material;
  p.lower.material.density *= density;
  p.lower.material.young_modulus *= density * shear_speed * shear_speed;
  p.lower.height = p.geometry.height; // FE: a lower block like the strip, absorbing below
  p.lower.bottom = TopBoundary::absorbing;
  return p;
}

SimulationParams coulomb(double n_d) {
  SimulationParams p = strip(Method::finite_element, n_d);
  p.friction.law = "coulomb";
  return p;
}

SimulationParams prakash_clifton(Method method, double n_d, double L) {
  SimulationParams p = strip(method, n_d);
  p.friction.L = L;
  return p;
}

// Plain Coulomb on the undamped lattice: a mesh-scale mode grows at a rate proportional to
// c_s / dx. Measured rate dx / c_s: 0.143, 0.142, 0.147 at n_d = 20, 40, 80; the bounds
// leave 25 % each side.
TEST(InterfaceGrowth, FeCoulombGrowsAtARateProportionalToCsOverDx) {
  for (double n_d : {20.0, 40.0, 80.0}) {
    const Growth g = growth_rate(coulomb(n_d));
    print("FE coulomb", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_GT(g.scaled, 0.107) << "n_d = " << n_d;
    EXPECT_LT(g.scaled, 0.18) << "n_d = " << n_d;
    EXPECT_GT(g.a_end, 1e-3) << "the perturbation grew by orders of magnitude";
  }
}

// Prakash-Clifton with L = 5e-6 m does not damp the mode on these meshes: the filter rate
// (|V| + V*)/L = 1020 /s is far above the mode's frequency (|V| + V*) dx / (L c_s) = 12.8 and
// 6.4 at n_d = 80 and 160), so the strength follows mu p as in Coulomb friction. Measured
// rate dx / c_s: 0.141, 0.146, 0.140 at n_d = 40, 80, 160 (n_d = 160 is not run here: it is
// the slowest case). With L = 5e-5 m the rate no longer scales with 1/dx: 3.61 and 3.69 /s
// at n_d = 40 and 80 (rate dx / c_s 0.090 -> 0.046).
TEST(InterfaceGrowth, FePrakashCliftonAtSmallLGrowsLikeCoulomb) {
  for (double n_d : {40.0, 80.0}) {
    const Growth g = growth_rate(prakash_clifton(Method::finite_element, n_d, 5e-6));
    print("FE prakash_clifton L = 5e-6", n_d, g);
    EXPECT_GT(g.scaled, 0.107) << "n_d = " << n_d;
    EXPECT_LT(g.scaled, 0.18) << "n_d = " << n_d;
  }
  for (double n_d : {40.0, 80.0}) {
    const Growth g = growth_rate(prakash_clifton(Method::finite_element, n_d, 5e-5));
    print("FE prakash_clifton L = 5e-5", n_d, g);
    EXPECT_GT(g.rate, 2.7) << "n_d = " << n_d; // 25 % below the measured 3.61 / 3.69 /s
    EXPECT_LT(g.rate, 4.6) << "n_d = " << n_d; // 25 % above
  }
}

// The mesh-scale damping -a K v, a = zeta dx / c_s: the damping rate of the mode, like its
// growth rate, is proportional to c_s / dx, so one zeta acts alike on every mesh. Measured
// (Coulomb) rate dx / c_s against zeta: 0.142 (0), 0.104-0.111 (0.01), 0.065-0.075 (0.02),
// 0.029-0.038 (0.03), 0.008-0.009 (0.04), < 0 from 0.05 at n_d = 40, 80, 160: the threshold
// is zeta_c = 0.045 +- 0.005. The rule takes zeta = 2 zeta_c, rounded up to 0.1: then the
// non-uniform part decays (rate -0.37, -0.36, -0.49 /s at n_d = 40, 80, 160, Prakash-Clifton
// L = 5e-6 m; -0.37 /s Coulomb n_d = 80), the slow decay of the radiating long waves. The
// bound 0.005 c_s / dx is 1/28 of the undamped rate; zeta = 0.03 must still grow (it pins
// the threshold the rule is taken from).
TEST(InterfaceGrowth, FeMeshDampingRemovesTheGrowth) {
  for (double n_d : {40.0, 80.0, 160.0}) {
    SimulationParams p = prakash_clifton(Method::finite_element, n_d, 5e-6);
    p.fe.mesh_damping = 0.1;
    const Growth g = growth_rate(p);
    print("FE prakash_clifton L = 5e-6, mesh_damping 0.1", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_LT(g.scaled, 0.005) << "n_d = " << n_d;
    EXPECT_LT(g.a_end, g.a_start) << "n_d = " << n_d;
  }
  SimulationParams p = coulomb(80.0);
  p.fe.mesh_damping = 0.1;
  const Growth g = growth_rate(p);
  print("FE coulomb, mesh_damping 0.1", 80.0, g);
  EXPECT_LT(g.scaled, 0.005);
  EXPECT_LT(g.a_end, g.a_start);
  p.fe.mesh_damping = 0.03;
  const Growth below = growth_rate(p);
  print("FE coulomb, mesh_damping 0.03", 80.0, below);
  EXPECT_GT(below.scaled, 0.02) << "zeta = 0.03 is below the threshold zeta_c";
}

// The spectral boundary-integral method (the exact half-space on the same interface grid):
// with Prakash-Clifton, L = 5e-6 m, no mesh-scale growth: measured 0.27, 0.46, 0.21 /s at
// n_d = 20, 40, 80 (0.72 /s at 160), rate dx / c_s <= 0.013, against 11.7 /s for FE at
// n_d = 80. Bound: 1 /s. With plain Coulomb at the default step (beta = 0.5) the BI lattice
// grows too, at 0.025, 0.027, 0.030 c_s / dx (n_d = 20, 40, 80; 0.030 at 160; 0.021 at
// beta = 0.4), but not at beta = 0.3 or 0.25 (-0.02 .. 0.01 /s at n_d = 40, 80, 160): the
// growth belongs to the time step of the scheme, not to the continuum, whose steady Coulomb
// sliding is stable for mu < 1 (tests/solver/reference/coulomb_stability.py). Bounds 25 %
// each side of the growing rates; "not growing": rate < 0.5 /s and the perturbation smaller
// at the end than after the pulse.
TEST(InterfaceGrowth, SpectralBiPrakashCliftonDoesNotGrowCoulombOnlyAtLongSteps) {
  for (double n_d : {40.0, 80.0}) {
    const Growth g = growth_rate(prakash_clifton(Method::spectral_bi, n_d, 5e-6));
    print("BI prakash_clifton L = 5e-6", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_LT(g.rate, 1.0) << "n_d = " << n_d;
    SimulationParams c = strip(Method::spectral_bi, n_d);
    c.friction.law = "coulomb";
    const Growth gc = growth_rate(c);
    print("BI coulomb", n_d, gc);
    EXPECT_GT(gc.scaled, 0.02) << "n_d = " << n_d;
    EXPECT_LT(gc.scaled, 0.037) << "n_d = " << n_d;
    c.spectral.time_step_factor = 0.25;
    const Growth short_step = growth_rate(c);
    print("BI coulomb, time_step_factor 0.25", n_d, short_step);
    EXPECT_LT(short_step.rate, 0.5) << "n_d = " << n_d;
    EXPECT_LT(short_step.a_end, short_step.a_start) << "n_d = " << n_d;
  }
}

// Two different elastic solids (BI, the contrast of the bimaterial presets; beta = 0.25, where
// the BI lattice itself grows nothing). Plain Coulomb friction is ill-posed there (Adams 1995;
// Ranjith & Rice 2001): steady sliding is unstable at every wavelength, with a growth rate
// Re(p) |k| c_s, so the finest mode the mesh holds grows fastest and the rate scales as 1/dx.
// The continuum's root for mu = 0.75 is p = 0.0322 - 0.9815 i (F = Kc11 + mu Kc21 = 0 with the
// interface relation of solver/spectral/bimaterial_relations.hpp;
// tests/solver/reference/bimaterial_coulomb_stability.py), i.e. rate dx / c_s =
// 0.0322 pi = 0.101 at k = pi / dx; measured 0.074, 0.079, 0.078 at n_d = 20, 40, 80 (the
// mesh's finest modes are not the continuum's). Prakash-Clifton (L = 5e-5 m) bounds it as
// dx -> 0: 2.16, 2.74, 3.08 /s at n_d = 40, 80, 160 (ratios 1.27, 1.12 per halving of dx,
// against 2 for Coulomb). Bounds: Coulomb rate dx / c_s within 25 % of 0.078 and below the
// continuum's 0.101; Prakash-Clifton below 4 /s with a ratio below 1.25 at the last halving.
TEST(InterfaceGrowth, SpectralBiBimaterialCoulombIsIllPosedPrakashCliftonBoundsIt) {
  for (double n_d : {20.0, 40.0, 80.0}) {
    SimulationParams c = on_lower_solid(strip(Method::spectral_bi, n_d));
    c.friction.law = "coulomb";
    c.spectral.time_step_factor = 0.25;
    const Growth g = growth_rate(c);
    print("BI bimaterial coulomb, time_step_factor 0.25", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_GT(g.scaled, 0.058) << "n_d = " << n_d;
    EXPECT_LT(g.scaled, 0.098) << "n_d = " << n_d;
    EXPECT_GT(g.a_end, 100 * g.a_start) << "the perturbation grew by orders of magnitude";
  }
  std::vector<double> rates;
  for (double n_d : {40.0, 80.0, 160.0}) {
    SimulationParams p = on_lower_solid(prakash_clifton(Method::spectral_bi, n_d, 5e-5));
    p.spectral.time_step_factor = 0.25;
    const Growth g = growth_rate(p);
    print("BI bimaterial prakash_clifton L = 5e-5, time_step_factor 0.25", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_LT(g.rate, 4.0) << "n_d = " << n_d;
    rates.push_back(g.rate);
  }
  EXPECT_LT(rates[2] / rates[1], 1.25) << "Prakash-Clifton's rate levels off as dx -> 0";
}

// The same two solids by FE: the lower block as high as the strip (1 m), absorbing below.
// Plain Coulomb grows at a rate proportional to 1/dx: measured dx / c_s 0.169, 0.171, 0.174
// at n_d = 20, 40, 80 (on the rigid plane the undamped FE lattice alone gives 0.143, see
// FeCoulombGrows... above: the FE rate is not the continuum's bimaterial root alone).
// Prakash-Clifton (L = 5e-5 m) bounds it as dx -> 0: 5.17, 6.21, 4.09 /s at n_d = 40, 80, 160
// (dx / c_s 0.129, 0.078, 0.026: not proportional to 1/dx). Bounds: Coulomb within 25 % of
// 0.172; Prakash-Clifton below 8 /s, not rising by more than 1.25 at the last halving.
TEST(InterfaceGrowth, FeBimaterialCoulombGrowsLikeOneOverDxPrakashCliftonBoundsIt) {
  for (double n_d : {20.0, 40.0, 80.0}) {
    const Growth g = growth_rate(on_lower_solid(coulomb(n_d)));
    print("FE bimaterial coulomb", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_GT(g.scaled, 0.129) << "n_d = " << n_d;
    EXPECT_LT(g.scaled, 0.215) << "n_d = " << n_d;
    EXPECT_GT(g.a_end, 100 * g.a_start) << "the perturbation grew by orders of magnitude";
  }
  std::vector<double> rates;
  for (double n_d : {40.0, 80.0, 160.0}) {
    const Growth g =
        growth_rate(on_lower_solid(prakash_clifton(Method::finite_element, n_d, 5e-5)));
    print("FE bimaterial prakash_clifton L = 5e-5", n_d, g);
    ASSERT_TRUE(g.finite);
    EXPECT_LT(g.rate, 8.0) << "n_d = " << n_d;
    rates.push_back(g.rate);
  }
  EXPECT_LT(rates[2] / rates[1], 1.25) << "Prakash-Clifton's rate levels off as dx -> 0";
}

// Not a check: one measurement chosen by environment variables (GROWTH_METHOD fe|bi,
// GROWTH_LAW pc|coulomb, GROWTH_L, GROWTH_ND, GROWTH_ZETA, GROWTH_BETA (BI time-step factor),
// GROWTH_Q (BI memory periods), GROWTH_T, GROWTH_LOWER rigid|bimaterial), for the studies of
// docs/small-l-study.md. Run with
// --gtest_also_run_disabled_tests.
TEST(InterfaceGrowth, DISABLED_Measure) {
  auto env = [](const char* name, const char* fallback) {
    const char* v = std::getenv(name);
    return std::string(v ? v : fallback);
  };
  const bool bi = env("GROWTH_METHOD", "fe") == "bi";
  const double n_d = std::stod(env("GROWTH_ND", "40"));
  SimulationParams p = strip(bi ? Method::spectral_bi : Method::finite_element, n_d);
  if (env("GROWTH_LAW", "pc") == "coulomb") p.friction.law = "coulomb";
  p.friction.L = std::stod(env("GROWTH_L", "5e-6"));
  p.fe.mesh_damping = std::stod(env("GROWTH_ZETA", "0"));
  p.spectral.time_step_factor = std::stod(env("GROWTH_BETA", "0.5"));
  p.spectral.memory_periods = std::stod(env("GROWTH_Q", "8"));
  if (env("GROWTH_LOWER", "rigid") == "bimaterial") p = on_lower_solid(p);
  const Growth g = growth_rate(p, std::stod(env("GROWTH_T", "6")));
  const std::string name = env("GROWTH_METHOD", "fe") + " " + env("GROWTH_LAW", "pc") + " L " +
                           env("GROWTH_L", "5e-6") + " zeta " + env("GROWTH_ZETA", "0") + " beta " +
                           env("GROWTH_BETA", "0.5") + " lower " + env("GROWTH_LOWER", "rigid");
  print(name.c_str(), n_d, g);
}

} // namespace
} // namespace slipfront
