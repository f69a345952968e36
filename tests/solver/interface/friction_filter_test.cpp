// Case 6: the strength update as a filter (paper Sec. 4 and appendix B) and its stability.
//
// d tau_s/dt = C (tau_s - mu p), C = -(|V| + V*)/L < 0. For a Coulomb input
// x(t) = mu p(t) = x0 + A0 sin(omega t) the steady output is
//   y = x0 + A sin(omega t + phi),  A/A0 = 1/sqrt(1 + (omega/C)^2),  phi = atan(omega/C) < 0
// (paper eq. B.6 with C < 0: the output lags).
//
// The "exponential" update (the reference scheme of docs/physics.md) advances tau_s^n =
// advance(tau_s^{n-1}, p^n) with the pressure of the step's end frozen over the step. For that
// recursion y_n = a y_{n-1} + (1 - a) x_n, a = exp(-r dt), r = -C, the exact discrete transfer
// function is H = (1 - a) / (1 - a exp(-i omega dt)) = H_continuum (1 + i omega dt / 2 + ...):
// a phase LEAD of omega dt / 2 (first order) and an amplitude error of second order. The
// test checks the measured response against H to round-off and against the paper's formula
// within these discretisation errors. The default "exponential_ramp" update takes the
// pressure linear over the step: exact for a linear input, second order for this one.
#include "verification_support.hpp"

#include "solver/interface/friction/strength_law.hpp"
#include "solver/interface/friction/strength_update.hpp"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>

namespace slipfront {
namespace {

using verification::measure;
constexpr double kPi = std::numbers::pi;

// The strength after one step of the law `f` (a constant coefficient: strength = c*).
double advance_strength(const Friction& f, double strength, double pressure_start,
                        double pressure_end, double slip_speed, double dt) {
  return StrengthLaw(f)
      .advance(f, FrictionState{strength, 0.0}, pressure_start, pressure_end, slip_speed, dt)
      .strength;
}

struct Response {
  double amplitude_ratio, phase;
};

// The rate |C| of the regularisation ODE: 1/t* (time scale) or (|V| + V*)/L (slip scale).
double filter_rate(const Friction& f, double V) {
  if (effective_regularization(f).description().name == std::string("time_scale"))
    return 1.0 / f.t_star;
  return (std::abs(V) + f.v_star) / f.L;
}

// Drives advance_strength with mu p(t) = x0 + A0 sin(omega t_n) and fits the steady output.
Response drive(const Friction& f, double V, double frequency, double dt) {
  const double r = filter_rate(f, V);
  const double omega = 2 * kPi * frequency;
  const double x0 = 0.01125, A0 = 0.3 * x0; // A0 < x0: the pressure stays compressive
  const double t_settle = 40.0 / r;         // transient exp(-r t) below 1e-17
  const double period = 1.0 / frequency;
  const long n_settle = long(std::ceil(t_settle / dt));
  const long n_fit = long(std::lround(3 * period / dt)); // three whole periods
  double y = x0;                                         // tau_s(0) = mu p0
  Eigen::Matrix3d AtA = Eigen::Matrix3d::Zero();
  Eigen::Vector3d Aty = Eigen::Vector3d::Zero();
  double pressure = x0 / f.mu;
  for (long n = 1; n <= n_settle + n_fit; ++n) {
    const double t = n * dt;
    const double previous = pressure;
    pressure = (x0 + A0 * std::sin(omega * t)) / f.mu;
    y = advance_strength(f, y, previous, pressure, std::abs(V), dt);
    if (n > n_settle) {
      const Eigen::Vector3d row(1.0, std::sin(omega * t), std::cos(omega * t));
      AtA += row * row.transpose();
      Aty += row * (y - x0);
    }
  }
  const Eigen::Vector3d c = AtA.ldlt().solve(Aty);
  return {std::hypot(c(1), c(2)) / A0, std::atan2(c(2), c(1))};
}

TEST(FrictionFilter, SinusoidalCoulombInputGivesThePapersAmplitudeAndPhase) {
  const double V = 1e-3;
  double worst_scheme = 0, worst_amp = 0, worst_phase = 0;
  for (double L : {1e-5, 1e-4, 1e-3}) {
    for (double q : {0.2, 1.0, 5.0}) { // q = omega L / (V* + |V|) = omega / |C|
      Friction f;
      f.L = L;
      f.update = StrengthUpdate::exponential;
      const double r = (V + f.v_star) / L;
      const double frequency = q * r / (2 * kPi);
      const double dt = std::min(1.0 / frequency, 1.0 / r) / 2000.0;
      const Response m = drive(f, V, frequency, dt);
      // The paper's (continuum) response.
      const double amp = 1.0 / std::sqrt(1.0 + q * q);
      const double phase = -std::atan(q);
      // The exact response of the discrete recursion.
      const double a = std::exp(-r * dt);
      const std::complex<double> H =
          (1 - a) / (1.0 - a * std::exp(std::complex<double>(0, -2 * kPi * frequency * dt)));
      const double e_scheme =
          std::max(std::abs(m.amplitude_ratio - std::abs(H)), std::abs(m.phase - std::arg(H)));
      const double e_amp = std::abs(m.amplitude_ratio / amp - 1);
      const double e_phase = m.phase - phase; // expected: + omega dt / 2
      const double lead = kPi * frequency * dt;
      EXPECT_LT(e_scheme, 1e-9) << "L = " << L << " q = " << q;
      EXPECT_LT(e_amp, 1e-5) << "L = " << L << " q = " << q;
      EXPECT_NEAR(e_phase, lead, 0.02 * lead) << "L = " << L << " q = " << q;
      EXPECT_LT(std::abs(e_phase), 2e-3);
      worst_scheme = std::max(worst_scheme, e_scheme);
      worst_amp = std::max(worst_amp, e_amp);
      worst_phase = std::max(worst_phase, std::abs(e_phase));
      measure(
          "filter L=%g f=%.4g Hz (omega/|C|=%g): A/A0 = %.8f (paper %.8f, rel. err %.2e), "
          "phase = %.8f (paper %.8f, diff %.3e = %.3f x omega dt/2), |meas - discrete H| = %.1e",
          L, frequency, q, m.amplitude_ratio, amp, e_amp, m.phase, phase, e_phase, e_phase / lead,
          e_scheme);
    }
  }
  measure("filter: worst |meas - discrete H| = %.2e, worst amplitude rel. err = %.2e, worst phase "
          "err = %.2e rad (dt = min(T, 1/|C|)/2000)",
          worst_scheme, worst_amp, worst_phase);
}

TEST(FrictionFilter, PhaseErrorIsFirstOrderInDtWithTheEndOfStepPressure) {
  Friction f;
  f.L = 1e-4;
  f.update = StrengthUpdate::exponential;
  const double V = 1e-3, r = (V + f.v_star) / f.L, frequency = r / (2 * kPi);
  double previous = 0;
  for (int N : {200, 400, 800}) {
    const double dt = 1.0 / (frequency * N);
    const double e = drive(f, V, frequency, dt).phase + std::atan(1.0);
    if (previous > 0) {
      EXPECT_NEAR(previous / e, 2.0, 0.02) << "N = " << N;
    }
    measure("filter phase error at %d steps per period: %.4e rad%s", N, e,
            previous > 0 ? "" : " (then halves with dt)");
    previous = e;
  }
}

// |y_n - x| after n steps from y_0 = x + 1 with a constant input x and a given dt |C|.
double deviation_after(StrengthUpdate update, double dt_rate, int steps) {
  Friction f;
  f.update = update;
  const double V = 2e-3, r = (V + f.v_star) / f.L, dt = dt_rate / r;
  const double p = 0.015, x = f.mu * p;
  double y = x + 1.0, worst = 0;
  for (int n = 0; n < steps; ++n) {
    const double y_new = advance_strength(f, y, p, p, V, dt);
    if (update != StrengthUpdate::explicit_euler) {
      // A contraction towards x without overshoot: same side, closer.
      EXPECT_GE((y_new - x) * (y - x), 0.0);
      EXPECT_LE(std::abs(y_new - x), std::abs(y - x));
    }
    y = y_new;
    worst = std::max(worst, std::abs(y - x));
    if (!std::isfinite(y)) return INFINITY;
  }
  return std::max(worst, std::abs(y - x));
}

TEST(FrictionFilter, ExponentialUpdatesAreStableForEveryStepExplicitEulerOnlyBelowTwo) {
  for (StrengthUpdate u : {StrengthUpdate::exponential, StrengthUpdate::exponential_ramp})
    for (double k : {0.5, 1.9, 2.1, 10.0, 100.0, 1e4}) {
      const double d = deviation_after(u, k, 500);
      EXPECT_LE(d, 1.0) << to_string(u) << ", dt|C| = " << k;
      measure("strength update %s dt|C| = %g: max |y - x| over 500 steps = %.3e (start 1)",
              to_string(u), k, d);
    }
  for (double k : {0.5, 1.0, 1.5, 1.9}) {
    const double d = deviation_after(StrengthUpdate::explicit_euler, k, 500);
    EXPECT_LE(d, 1.0) << "explicit Euler, dt|C| = " << k;
    measure("strength update explicit Euler dt|C| = %g: max |y - x| over 500 steps = %.3e", k, d);
  }
  for (double k : {2.1, 2.5, 10.0, 100.0}) {
    const double d = deviation_after(StrengthUpdate::explicit_euler, k, 500);
    EXPECT_GT(d, 1e15) << "explicit Euler, dt|C| = " << k << " should blow up";
    measure("strength update explicit Euler dt|C| = %g: max |y - x| over 500 steps = %.3e "
            "(|1 - dt|C||^500 = %.3e)",
            k, d, std::pow(std::abs(1 - k), 500));
  }
}

TEST(FrictionFilter, CoulombLawIsMuTimesCompressivePressure) {
  Friction f;
  f.law = "coulomb";
  EXPECT_EQ(advance_strength(f, 123.0, 0.01, 0.02, 1.0, 0.1), 0.75 * 0.02);
  EXPECT_EQ(advance_strength(f, 123.0, 0.01, -0.02, 1.0, 0.1), 0.0);
  f.law = "prakash_clifton"; // tends to mu max(0, p): an open node loses strength
  double y = 0.01;
  for (int n = 0; n < 1000; ++n)
    y = advance_strength(f, y, -0.02, -0.02, 1e-3, 0.01);
  EXPECT_LT(std::abs(y), 1e-12);
}

TEST(FrictionFilter, RampUpdateIsExactForAPressureLinearOverTheStep) {
  // One step against the closed-form solution of tau' = -k (tau - c(t)), c linear from c0
  // to c1, written independently: tau(t) = c(t) + s/k ... with s = (c1 - c0)/dt, i.e.
  // tau(t) = c(t) - s/k + (tau0 - c0 + s/k) exp(-k t).
  Friction f;
  for (double x : {1e-6, 1e-3, 0.3, 1.0, 7.0, 300.0}) { // k dt
    for (double p1 : {0.0, 0.012, 0.03}) {
      const double p0 = 0.015, tau0 = 0.0105, V = 2e-3, dt = 0.01;
      f.L = dt * (V + f.v_star) / x;
      const double k = (V + f.v_star) / f.L, c0 = f.mu * p0, c1 = f.mu * p1, s = (c1 - c0) / dt;
      const double exact = c1 - s / k + (tau0 - c0 + s / k) * std::exp(-k * dt);
      const double ramp = advance_strength(f, tau0, p0, p1, V, dt);
      // The reference cancels terms of size s/k: its own rounding is about 1e-16 |s/k|.
      EXPECT_NEAR(ramp, exact, 1e-13 + 1e-14 * std::abs(s / k)) << "k dt = " << x << " p1 " << p1;
      // A convex combination of tau0, c0 and c1: never outside their range.
      EXPECT_GE(ramp, std::min({tau0, c0, c1}) - 1e-18);
      EXPECT_LE(ramp, std::max({tau0, c0, c1}) + 1e-18);
    }
  }
}

TEST(FrictionFilter, RampUpdateStaysWithinItsInputsUnderAJumpingPressure) {
  // The pressure jumps between 0 (open) and 0.03 Pa every step, at dt|C| up to 1e4: each
  // result lies within the range of the previous strength and the two targets.
  Friction f;
  for (double x : {0.5, 10.0, 1e4}) {
    const double V = 2e-3, dt = 0.01;
    f.L = dt * (V + f.v_star) / x;
    double tau = 0.0105, p = 0.015;
    for (int n = 0; n < 200; ++n) {
      const double p_next = n % 2 ? 0.0 : 0.03;
      const double c0 = f.mu * p, c1 = f.mu * p_next;
      const double next = advance_strength(f, tau, p, p_next, V, dt);
      ASSERT_GE(next, std::min({tau, c0, c1}) - 1e-18) << "dt|C| = " << x << " step " << n;
      ASSERT_LE(next, std::max({tau, c0, c1}) + 1e-18) << "dt|C| = " << x << " step " << n;
      tau = next;
      p = p_next;
    }
  }
}

TEST(FrictionFilter, RampUpdateIsSecondOrderInDt) {
  // Sinusoidal input at omega = |C|: the response error against the paper's (amplitude
  // 1/sqrt(2), phase -atan(1)) falls by 4 per halving of dt (the end-of-step pressure: its
  // phase error by 2, test above).
  Friction f;
  f.L = 1e-4;
  const double V = 1e-3, r = (V + f.v_star) / f.L, frequency = r / (2 * kPi);
  double previous = 0;
  for (int N : {50, 100, 200}) {
    const double dt = 1.0 / (frequency * N);
    const Response m = drive(f, V, frequency, dt);
    const double e = std::hypot(m.phase + std::atan(1.0), m.amplitude_ratio - std::sqrt(0.5));
    if (previous > 0) {
      EXPECT_NEAR(previous / e, 4.0, 0.1) << "N = " << N;
    }
    measure("ramp update, %d steps per period: response error %.4e%s", N, e,
            previous > 0 ? "" : " (then falls by 4 with each halving of dt)");
    previous = e;
  }
}

// The time-scale regularisation, d c*/dt = -(c* - mu max(0, p)) / t* (docs/physics.md): the
// same exact updates with k = 1/t*, whatever the slip speed.
Friction time_scale(double t_star, StrengthUpdate update) {
  Friction f;
  f.law = "coulomb";
  f.regularization = "time_scale";
  f.t_star = t_star;
  f.update = update;
  return f;
}

TEST(FrictionFilter, TimeScaleStepResponseIsTheExactExponential) {
  // The pressure steps from p0 to p1 at t = 0 and stays: c*(t) = mu p1 + mu (p0 - p1) e^(-t/t*).
  // The exponential update holds c at the step's end value: exact at every step, any dt.
  const double p0 = 0.015, p1 = 0.006, t_star = 0.05;
  double worst = 0;
  for (double dt_over_t : {0.01, 1.0, 10.0}) {
    const Friction f = time_scale(t_star, StrengthUpdate::exponential);
    const double dt = dt_over_t * t_star;
    double y = f.mu * p0;
    for (int n = 1; n <= 200; ++n) {
      y = advance_strength(f, y, n == 1 ? p0 : p1, p1, 0.3, dt);
      const double exact = f.mu * p1 + f.mu * (p0 - p1) * std::exp(-n * dt / t_star);
      ASSERT_NEAR(y, exact, 1e-13 * f.mu * p0) << "dt/t* = " << dt_over_t << " step " << n;
      worst = std::max(worst, std::abs(y - exact));
    }
  }
  // The slip speed does not enter (it does in the slip scale).
  for (StrengthUpdate u : {StrengthUpdate::exponential, StrengthUpdate::exponential_ramp}) {
    const Friction f = time_scale(t_star, u);
    EXPECT_EQ(advance_strength(f, 0.01, p0, p1, 0.0, 0.01),
              advance_strength(f, 0.01, p0, p1, 5.0, 0.01));
  }
  measure("time-scale step response: worst |c* - exact exponential| = %.2e Pa over 200 steps "
          "at dt/t* = 0.01, 1, 10",
          worst);
}

TEST(FrictionFilter, TimeScaleRampUpdateIsSecondOrderInDt) {
  // As RampUpdateIsSecondOrderInDt with |C| = 1/t*: the response at omega = 1/t* has the
  // amplitude 1/sqrt(2) and the phase -atan(1); the error falls by 4 per halving of dt.
  const Friction f = time_scale(0.05, StrengthUpdate::exponential_ramp);
  const double frequency = 1.0 / (f.t_star * 2 * kPi);
  double previous = 0;
  for (int N : {50, 100, 200}) {
    const double dt = 1.0 / (frequency * N);
    const Response m = drive(f, 1e-3, frequency, dt);
    const double e = std::hypot(m.phase + std::atan(1.0), m.amplitude_ratio - std::sqrt(0.5));
    if (previous > 0) {
      EXPECT_NEAR(previous / e, 4.0, 0.1) << "N = " << N;
    }
    measure("time-scale ramp update, %d steps per period: response error %.4e", N, e);
    previous = e;
  }
}

} // namespace
} // namespace slipfront
