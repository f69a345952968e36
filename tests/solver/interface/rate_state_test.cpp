// Rate-and-state friction alone (solver/interface/friction/rate_state_math.hpp) against its
// closed forms (docs/verification.md "Rate-and-state friction"): the steady state mu_ss(V),
// theta(t) at a constant slip rate for both state laws (and against a fine Runge-Kutta
// integration of the ODE, which knows nothing of the closed forms), a velocity step (the
// direct effect a ln(V2/V1) at once, then the decay over D_c to the new steady state), the
// initial state of SCEC TPV101, and the implicit solve of the slip rate.
#include "solver/interface/friction/rate_state_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace slipfront::rate_state {
namespace {

// The SEM2DPACK example's values (docs/presets.md, the preset `rsf_slip_law_inplane`).
Parameters kaneko() {
  return {0.0125, 0.0172, 0.037, 0.6, 1e-6};
}

// The classical logarithmic form, which the sinh form approaches once V >> 2 V* exp(-psi/a).
double log_form(const Parameters& p, double v, double theta) {
  return p.f0 + p.a * std::log(v / p.v_star) + p.b * std::log(p.v_star * theta / p.D_c);
}

TEST(RateState, SteadyStateIsTheLogarithmicLawAwayFromZero) {
  const Parameters p = kaneko();
  // At V*: f0 (the sinh form differs from the log by a e^(-2 f0/a) ~ 1e-43 here).
  EXPECT_NEAR(steady_state_coefficient(p, p.v_star), p.f0, 1e-14);
  for (double v = 1e-12; v < 1e3; v *= 10.0) {
    const double expected = p.f0 + (p.a - p.b) * std::log(v / p.v_star);
    EXPECT_NEAR(steady_state_coefficient(p, v), expected, 1e-12) << "V = " << v;
    EXPECT_DOUBLE_EQ(steady_state_theta(p, v), p.D_c / v);
  }
  // Near V = 0 the sinh form stays finite and goes to 0 linearly (the log form -> -inf).
  EXPECT_EQ(coefficient(p, 0.0, 1.0), 0.0);
  const double c = 2.0 * p.v_star * std::exp(-log_form(p, p.v_star, 1.0) / p.a);
  const double tiny = 1e-6 * c;
  EXPECT_NEAR(coefficient(p, tiny, 1.0), p.a * tiny / c, 1e-9 * p.a * tiny / c);
}

TEST(RateState, CoefficientHoldsAtExtremeStates) {
  const Parameters p = kaneko();
  // theta from 4e-14 s (the SEM2DPACK example outside 10 km) to 1e12 s, V from 1e-20 to
  // 1e3 m/s: finite, >= 0, and the log form wherever z >> 1.
  for (double theta : {4.0036e-14, 1e-6, 92.713, 1e12})
    for (double v = 1e-20; v < 2e3; v *= 100.0) {
      const double mu = coefficient(p, v, theta);
      ASSERT_TRUE(std::isfinite(mu) && mu >= 0.0) << v << " " << theta;
      const double log_z = std::log(v / (2 * p.v_star)) + (log_form(p, p.v_star, theta)) / p.a;
      if (log_z > 5.0) {
        EXPECT_NEAR(mu, log_form(p, v, theta), 1e-4 * p.a) << v << " " << theta;
      }
      ASSERT_TRUE(std::isfinite(coefficient_slope(p, v, theta)));
    }
  // The slope is the derivative: a central difference agrees.
  const double v = 3e-3, theta = 0.5, h = 1e-9;
  const double numeric = (coefficient(p, v + h, theta) - coefficient(p, v - h, theta)) / (2 * h);
  EXPECT_NEAR(coefficient_slope(p, v, theta), numeric, 1e-6 * numeric);
}

// theta' of a state law (the ODE as written in docs/physics.md).
double rate(StateLaw law, const Parameters& p, double theta, double v) {
  const double x = v * theta / p.D_c;
  return law == StateLaw::aging ? 1.0 - x : -x * std::log(x);
}

// Classical fourth-order Runge-Kutta over t with n steps.
double runge_kutta(StateLaw law, const Parameters& p, double theta, double v, double t, int n) {
  const double h = t / n;
  for (int i = 0; i < n; ++i) {
    const double k1 = rate(law, p, theta, v);
    const double k2 = rate(law, p, theta + 0.5 * h * k1, v);
    const double k3 = rate(law, p, theta + 0.5 * h * k2, v);
    const double k4 = rate(law, p, theta + h * k3, v);
    theta += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return theta;
}

TEST(RateState, StateAtConstantSlipRateIsExact) {
  const Parameters p = kaneko();
  const double v = 0.05, theta0 = 92.713; // far above steady state D_c/V = 0.74 s
  for (double t : {1e-3, 0.1, 0.74, 3.0}) {
    const double aging = p.D_c / v + (theta0 - p.D_c / v) * std::exp(-v * t / p.D_c);
    const double slip = p.D_c / v * std::pow(theta0 * v / p.D_c, std::exp(-v * t / p.D_c));
    EXPECT_NEAR(evolve_state(StateLaw::aging, p, theta0, v, t), aging, 1e-12 * aging);
    EXPECT_NEAR(evolve_state(StateLaw::slip, p, theta0, v, t), slip, 1e-12 * slip);
    // The ODE integrated without the closed form.
    EXPECT_NEAR(runge_kutta(StateLaw::aging, p, theta0, v, t, 20000), aging, 1e-9 * aging);
    EXPECT_NEAR(runge_kutta(StateLaw::slip, p, theta0, v, t, 20000), slip, 1e-9 * slip);
    std::printf("[measure] theta(t = %g s) at V = %g m/s: aging %.10g s, slip %.10g s\n", t, v,
                aging, slip);
  }
  // Exact means that steps compose: 1000 steps of t/1000 are one step of t.
  for (StateLaw law : {StateLaw::aging, StateLaw::slip}) {
    double theta = theta0;
    for (int i = 0; i < 1000; ++i)
      theta = evolve_state(law, p, theta, v, 1e-3);
    const double once = evolve_state(law, p, theta0, v, 1.0);
    EXPECT_NEAR(theta, once, 1e-11 * once);
  }
  // At rest: aging heals linearly in time, the slip law does not evolve.
  EXPECT_DOUBLE_EQ(evolve_state(StateLaw::aging, p, 2.0, 0.0, 0.5), 2.5);
  EXPECT_EQ(evolve_state(StateLaw::slip, p, 2.0, 0.0, 0.5), 2.0);
  // A very slow slip rate (1e-300 m/s) is at rest to double precision, not a NaN.
  EXPECT_DOUBLE_EQ(evolve_state(StateLaw::aging, p, 2.0, 1e-300, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(evolve_state(StateLaw::slip, p, 2.0, 1e-300, 0.5), 2.0);
}

TEST(RateState, VelocityStepDirectEffectThenDecayOverDc) {
  const Parameters p = kaneko();
  const double v1 = 1e-6, v2 = 1e-4;
  for (StateLaw law : {StateLaw::aging, StateLaw::slip}) {
    double theta = steady_state_theta(p, v1);
    const double before = coefficient(p, v1, theta);
    // The direct effect: mu jumps by a ln(V2/V1) with the state unchanged.
    EXPECT_NEAR(coefficient(p, v2, theta) - before, p.a * std::log(v2 / v1), 1e-12);
    // Then the state relaxes over slip: after a slip delta at V2, the slip law's ln theta
    // is exponential in delta, so mu - mu_ss(V2) = b ln(V2/V1) exp(-delta/D_c) exactly (in
    // the logarithmic regime); the aging law's decay is exponential in slip too at constant V.
    const double after = steady_state_coefficient(p, v2);
    const double step = 0.1 * p.D_c / v2; // each step slips D_c / 10
    for (int n = 1; n <= 100; ++n) {
      theta = evolve_state(law, p, theta, v2, step);
      const double delta = n * 0.1 * p.D_c;
      const double mu = coefficient(p, v2, theta);
      if (law == StateLaw::slip) {
        ASSERT_NEAR(mu - after, p.b * std::log(v2 / v1) * std::exp(-delta / p.D_c), 1e-12);
      } else { // aging: theta = theta_ss2 + (theta_ss1 - theta_ss2) e^(-delta/D_c)
        const double th = p.D_c / v2 + (p.D_c / v1 - p.D_c / v2) * std::exp(-delta / p.D_c);
        ASSERT_NEAR(mu, log_form(p, v2, th), 1e-12);
      }
    }
    // After 10 D_c: the slip law is b ln(100) e^-10 = 3.6e-6 above mu_ss(V2); the aging law,
    // b ln(1 + 99 e^-10) = 7.7e-5 (its theta, not ln theta, decays exponentially).
    const double left = law == StateLaw::slip ? p.b * std::log(v2 / v1) * std::exp(-10.0)
                                              : p.b * std::log1p((v2 / v1 - 1) * std::exp(-10.0));
    EXPECT_NEAR(coefficient(p, v2, theta) - after, left, 1e-12);
  }
}

TEST(RateState, InitialStateOfTpv101) {
  // TPV101: tau0 = 75 MPa, sigma = 120 MPa, V_ini = 1e-12 m/s, a = 0.008, b = 0.012,
  // D_c = 0.02 m, f0 = 0.6, V* = 1e-6 m/s: theta makes the strength equal tau0.
  const Parameters p{0.008, 0.012, 0.02, 0.6, 1e-6};
  const double theta = theta_for_coefficient(p, 1e-12, 75.0 / 120.0);
  EXPECT_NEAR(coefficient(p, 1e-12, theta), 0.625, 1e-13);
  std::printf("[measure] TPV101 initial theta inside the fault: %.6e s\n", theta);
  // The SEM2DPACK example's stated theta gives its stated coefficient 0.58333 at 1e-3 m/s.
  EXPECT_NEAR(coefficient(kaneko(), 1e-3, 92.713), 0.58333, 5e-6);
  EXPECT_NEAR(theta_for_coefficient(kaneko(), 1e-3, 70.0 / 120.0), 92.713, 1e-3);
}

TEST(RateState, SlipRateSolveMeetsTheImpedanceRelation) {
  // tau_lock - eta V = sigma mu(|V|, theta) sign V over a sweep of states, drives and
  // impedances; V in the bracket, with the sign of tau_lock, in few iterations.
  const Parameters p = kaneko();
  const double sigma = 120e6, eta = 2670.0 * 3464.0 / 2.0;
  int worst = 0;
  for (double theta : {4.0036e-14, 1e-3, 0.74, 92.713, 1e9})
    for (double tau = -100e6; tau <= 100e6; tau += 12.5e6)
      for (double guess : {0.0, 1e-3, 10.0}) {
        const SlipRateSolve s = solve_slip_rate(p, theta, sigma, eta, tau, guess);
        worst = std::max(worst, s.iterations);
        ASSERT_LE(std::abs(s.slip_rate), std::abs(tau) / eta * (1 + 1e-15));
        ASSERT_TRUE(s.slip_rate * tau >= 0.0);
        const double v = std::abs(s.slip_rate);
        const double residual = std::abs(tau) - eta * v - sigma * coefficient(p, v, theta);
        // The residual is at the rounding of the larger terms (tau up to 1e8 Pa).
        ASSERT_LE(std::abs(residual), 1e-6 + 1e-13 * std::abs(tau))
            << "theta " << theta << " tau " << tau << " guess " << guess;
      }
  std::printf("[measure] slip-rate solve: at most %d iterations over the sweep\n", worst);
  EXPECT_LE(worst, 12); // Newton in ln V: 9 measured
  // No normal stress: no strength, V = tau_lock / eta. No drive: at rest.
  EXPECT_DOUBLE_EQ(solve_slip_rate(p, 1.0, 0.0, eta, -4e6).slip_rate, -4e6 / eta);
  EXPECT_EQ(solve_slip_rate(p, 1.0, sigma, eta, 0.0).slip_rate, 0.0);
  // At the SEM2DPACK example's initial state inside 10 km, V stays 1e-3 m/s but for the
  // impedance's share: tau0 - eta V = strength(V) with tau0 = strength(1e-3 m/s).
  const double tau0 = sigma * coefficient(p, 1e-3, 92.713);
  const double v0 = solve_slip_rate(p, 92.713, sigma, eta, tau0 + eta * 1e-3).slip_rate;
  EXPECT_NEAR(v0, 1e-3, 1e-15);
}

} // namespace
} // namespace slipfront::rate_state
