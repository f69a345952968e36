#include "solver/interface/nucleation.hpp"

#include <cmath>
#include <limits>

namespace slipfront {

namespace {
double eta0(const Nucleation& n) {
  return std::sqrt(n.a * n.a + n.b * n.b) / n.b;
}
} // namespace

double nucleation_traction(const Nucleation& n, double normal_stress, double x1, double t) {
  if (!n.ellipse()) return 0.0;
  const double xi = (x1 - n.v * t) / n.a;
  const double eta = (x1 + n.v * t) / n.b - eta0(n);
  const double inside = 1.0 - xi * xi - eta * eta;
  if (inside <= 0.0) return 0.0;
  return n.alpha * std::abs(normal_stress) * inside * inside;
}

double nucleation_shear_traction(const Nucleation& n, double x1, double t) {
  if (!n.perturbation() || !(t > 0.0)) return 0.0;
  const double r2 = (x1 - n.x1) * (x1 - n.x1), R2 = n.radius * n.radius;
  if (!(r2 < R2)) return 0.0;
  const double F = std::exp(r2 / (r2 - R2));
  const double T = n.rise_time;
  const double G = t < T ? std::exp((t - T) * (t - T) / (t * (t - 2.0 * T))) : 1.0;
  return n.shear_stress_increase * F * G;
}

// In the coordinates p = x1 - v t, q = x1 + v t - b eta0 the ellipse is p^2/a^2 + q^2/b^2 <= 1,
// and x1 = (p + q + b eta0)/2, v t = (q - p + b eta0)/2. The extremes of p + q and q - p
// over the ellipse are +-sqrt(a^2 + b^2).
Interval nucleation_patch(const Nucleation& n) {
  if (n.patch()) return {n.x1_min, n.x1_max};
  if (n.perturbation()) return {n.x1 - n.radius, n.x1 + n.radius};
  if (!n.ellipse()) {
    const double inf = std::numeric_limits<double>::infinity();
    return {inf, -inf};
  }
  const double r = std::sqrt(n.a * n.a + n.b * n.b);
  const double c = n.b * eta0(n); // = r
  return {(c - r) / 2.0, (c + r) / 2.0};
}

double nucleation_end_time(const Nucleation& n) {
  if (n.perturbation()) return n.rise_time;
  if (!n.ellipse()) return 0.0;
  const double r = std::sqrt(n.a * n.a + n.b * n.b);
  return (n.b * eta0(n) + r) / (2.0 * n.v);
}

} // namespace slipfront
