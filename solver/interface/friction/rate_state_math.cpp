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

// asinh(exp(log_z)) without forming exp(log_z) when it is large.
double asinh_of_exp(double log_z) {
  if (log_z < 20.0) return std::asinh(std::exp(log_z));
  return log_z + std::log(1.0 + std::sqrt(1.0 + std::exp(-2.0 * log_z)));
}

// (1 - exp(-x)) / x, 1 at x = 0: the weight of the steady state after a slip of x D_c.
double relaxed_fraction(double x) {
  return x > 0.0 ? -std::expm1(-x) / x : 1.0;
}

} // namespace

double coefficient(const Parameters& p, double slip_rate, double theta) {
  if (!(slip_rate > 0.0)) return 0.0;
  return p.a * asinh_of_exp(std::log(slip_rate / (2.0 * p.v_star)) + state_exponent(p, theta));
}

double coefficient_slope(const Parameters& p, double slip_rate, double theta) {
  const double c = 2.0 * p.v_star * std::exp(-state_exponent(p, theta));
  return p.a / std::hypot(slip_rate, c);
}

double evolve_state(StateLaw law, const Parameters& p, double theta, double slip_rate, double dt) {
  const double x = std::abs(slip_rate) * dt / p.D_c; // slip over the step in units of D_c
  const double decay = std::exp(-x);
  if (law == StateLaw::aging) // theta e^-x + (D_c/V)(1 - e^-x), written to hold at V = 0
    return theta * decay + dt * relaxed_fraction(x);
  if (x == 0.0) return theta;
  const double log_steady = std::log(p.D_c / std::abs(slip_rate));
  return std::exp(decay * std::log(theta) - std::expm1(-x) * log_steady);
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
  auto residual = [&](double u, double& slope) {
    const double log_z = u - log_scale;
    const double v = std::exp(u);
    slope = -eta * v - sigma * p.a / std::sqrt(1.0 + std::exp(-2.0 * log_z)); // h'(u)
    return drive - eta * v - sigma * p.a * asinh_of_exp(log_z);
  };
  const double u_max = std::log(drive / eta); // h(u_max) = -sigma mu <= 0
  double u = u_max;
  if (std::abs(guess) > 0.0 && std::abs(guess) < drive / eta) u = std::log(std::abs(guess));
  constexpr int max_iterations = 100;
  for (int k = 1; k <= max_iterations; ++k) {
    out.iterations = k;
    double slope = 0.0;
    const double h = residual(u, slope);
    if (h == 0.0) break;
    const double step = -h / slope;
    const double next = std::min(u + step, u_max);
    const bool converged = std::abs(next - u) <= 1e-14 * std::max(1.0, std::abs(u));
    u = next;
    if (converged) break;
  }
  out.slip_rate = sign * std::exp(u);
  return out;
}

} // namespace slipfront::rate_state
