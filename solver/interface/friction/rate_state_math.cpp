#include "solver/interface/friction/rate_state_math.hpp"

#include <cmath>
#include <limits>
#include <numbers>

namespace slipfront::rate_state {

namespace {

// psi / a, psi = f0 + b ln(V* theta / D_c): the state's share of ln z.
double state_exponent(const Parameters& p, double theta) {
  return (p.f0 + p.b * std::log(p.v_star * theta / p.D_c)) / p.a;
}

// asinh z at z = exp(log_z), and its slope in ln z, d asinh(z) / d ln z = z / sqrt(1 + z^2),
// without forming z when it is large (there asinh z = ln(2z) + 1/(4z^2) - ..., and the
// correction is below a double's resolution of ln 2z once ln z >= 20). `z` is exp(log_z)
// when the caller has it (else NaN). asinh z = log1p(z + z^2 / (1 + sqrt(1 + z^2))) keeps its
// relative accuracy for small z.
struct AsinhOfExp {
  double value;
  double slope;
};
AsinhOfExp asinh_of_exp(double log_z, double z = std::numeric_limits<double>::quiet_NaN()) {
  if (log_z >= 20.0) return {log_z + std::numbers::ln2, 1.0};
  if (std::isnan(z)) z = std::exp(log_z);
  const double root = std::sqrt(1.0 + z * z);
  return {std::log1p(z + z * z / (1.0 + root)), z / root};
}

// (1 - exp(-x)) / x, 1 at x = 0: the weight of the steady state after a slip of x D_c.
double relaxed_fraction(double x) {
  return x > 0.0 ? -std::expm1(-x) / x : 1.0;
}

} // namespace

double coefficient(const Parameters& p, double slip_rate, double theta) {
  if (!(slip_rate > 0.0)) return 0.0;
  return p.a *
         asinh_of_exp(std::log(slip_rate / (2.0 * p.v_star)) + state_exponent(p, theta)).value;
}

double coefficient_slope(const Parameters& p, double slip_rate, double theta) {
  const double c = 2.0 * p.v_star * std::exp(-state_exponent(p, theta));
  return p.a / std::hypot(slip_rate, c);
}

double evolve_state(StateLaw law, const Parameters& p, double theta, double slip_rate, double dt) {
  const double x = std::abs(slip_rate) * dt / p.D_c; // slip over the step in units of D_c
  if (law == StateLaw::aging) // theta e^-x + (D_c/V)(1 - e^-x), written to hold at V = 0
    return theta * std::exp(-x) + dt * relaxed_fraction(x);
  if (x == 0.0) return theta;
  const double decay_minus_one = std::expm1(-x); // e^-x - 1, exact for small x
  const double log_steady = std::log(p.D_c / std::abs(slip_rate));
  return std::exp((1.0 + decay_minus_one) * std::log(theta) - decay_minus_one * log_steady);
}

double steady_state_theta(const Parameters& p, double slip_rate) {
  return p.D_c / slip_rate;
}

double steady_state_coefficient(const Parameters& p, double slip_rate) {
  return coefficient(p, slip_rate, steady_state_theta(p, slip_rate));
}

double theta_for_coefficient(const Parameters& p, double slip_rate, double mu) {
  // z = sinh(mu/a) = V/(2 V*) exp(psi/a)  =>  psi = a ln(2 V* sinh(mu/a) / V),
  // then ln(V* theta / D_c) = (psi - f0) / b. ln sinh y = y + ln((1 - e^-2y)/2).
  const double y = mu / p.a;
  const double log_sinh = y + std::log1p(-std::exp(-2.0 * y)) - std::numbers::ln2;
  const double psi = p.a * (std::log(2.0 * p.v_star / slip_rate) + log_sinh);
  return p.D_c / p.v_star * std::exp((psi - p.f0) / p.b);
}

SlipRateSolve solve_slip_rate(const Parameters& p, double theta, double sigma, double eta,
                              double tau_lock, double guess) {
  SlipRateSolve out;
  const double drive = std::abs(tau_lock);
  const double sign = tau_lock < 0.0 ? -1.0 : 1.0;
  if (drive == 0.0) return out;
  if (!(sigma > 0.0)) { // no normal stress: no strength
    out.slip_rate = sign * drive / eta;
    return out;
  }
  // In u = ln V the residual h(u) = drive - eta e^u - sigma a asinh(e^u / c) is decreasing
  // and concave (both terms are), so Newton's iteration started where h <= 0 falls
  // monotonically onto the root, and started where h > 0 overshoots once, then falls. In the
  // logarithmic regime h is nearly linear in u, so a step or two suffice where a solve in V
  // would creep down through decades.
  const double log_scale = std::log(2.0 * p.v_star) - state_exponent(p, theta); // ln c
  // z = V / c = e^u / c: formed as a product where 1/c is a finite double (one exp per
  // iteration, not two).
  const double inverse_scale = std::exp(-log_scale);
  const bool scale_is_finite = std::isfinite(inverse_scale) && inverse_scale > 0.0;
  auto residual = [&](double u, double& slope) {
    const double v = std::exp(u);
    const double z = scale_is_finite ? v * inverse_scale : std::numeric_limits<double>::quiet_NaN();
    const AsinhOfExp mu = asinh_of_exp(u - log_scale, z);
    slope = -eta * v - sigma * p.a * mu.slope; // h'(u)
    return drive - eta * v - sigma * p.a * mu.value;
  };
  const double u_max = std::log(drive / eta); // h(u_max) = -sigma mu <= 0
  double u = u_max;
  if (std::abs(guess) > 0.0 && std::abs(guess) < drive / eta) u = std::log(std::abs(guess));
  // Where z = V/c is small at the root, asinh z = z (1 - z^2/6 + ...) makes the relation
  // linear: V_lin = drive / (eta + sigma a / c) is a root to within z^2/6 in ln V. Newton
  // started far on the side where the exponential dominates creeps by one unit of ln V per
  // iteration, so a node locked or at almost no strength starts there instead (h(u_lin) >= 0,
  // since asinh z <= z: Newton's first step overshoots, then falls onto the root).
  if (scale_is_finite) {
    const double v_lin = drive / (eta + sigma * p.a * inverse_scale);
    if (v_lin * inverse_scale < 0.1 && v_lin > 0.0) u = std::log(v_lin);
  }
  // Newton converges quadratically here (h'' / h' is of order one in u): once a step is below
  // 1e-9 (relative), the error it leaves is of order 1e-18 u^2, under a double's resolution of u.
  constexpr int max_iterations = 100;
  for (int k = 1; k <= max_iterations; ++k) {
    out.iterations = k;
    double slope = 0.0;
    const double h = residual(u, slope);
    if (h == 0.0) break;
    const double step = -h / slope;
    const double next = std::min(u + step, u_max);
    const bool converged = std::abs(next - u) <= 1e-9 * std::max(1.0, std::abs(u));
    u = next;
    if (converged) break;
  }
  out.slip_rate = sign * std::exp(u);
  return out;
}

} // namespace slipfront::rate_state
