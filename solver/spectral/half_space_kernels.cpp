#include "solver/spectral/half_space_kernels.hpp"

#include <boost/math/quadrature/gauss.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace slipfront::spectral {

namespace {

using complex = std::complex<double>;
constexpr double pi = std::numbers::pi;

// Gauss-Legendre rule (20 points) mapped to [lo, hi]: appends (x, weight) pairs.
template <class Emit> void gauss_legendre_20(double lo, double hi, Emit&& emit) {
  using rule = boost::math::quadrature::gauss<double, 20>;
  const double half = 0.5 * (hi - lo), mid = 0.5 * (hi + lo);
  const auto& x = rule::abscissa();
  const auto& w = rule::weights();
  for (std::size_t i = 0; i < x.size(); ++i) {
    emit(mid - half * x[i], half * w[i]);
    emit(mid + half * x[i], half * w[i]);
  }
}

// Cubic Hermite interpolation on [0, 1] of values f0, f1 and slopes d0, d1 (per unit s).
double hermite(double s, double f0, double f1, double d0, double d1) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * f0 + (s3 - 2 * s2 + s) * d0 + (-2 * s3 + 3 * s2) * f1 +
         (s3 - s2) * d1;
}

} // namespace

ModeStiffness mode_stiffness(complex p, double r) {
  const complex a = std::sqrt(1.0 + r * r * p * p);
  const complex b = std::sqrt(1.0 + p * p);
  const complex q = 1.0 + r * r + r * r * p * p;
  const complex one_ab = 1.0 + a * b;
  return {-a * one_ab / q, -b * one_ab / q, 2.0 - one_ab / q};
}

ModeStiffness static_stiffness(double r) {
  const double s = 2.0 / (1.0 + r * r);
  return {-s, -s, 2.0 * r * r / (1.0 + r * r)};
}

HalfSpaceKernels::HalfSpaceKernels(double r, double t_max) : r_(r), t_max_(t_max) {
  if (!(r > 0.0 && r < 1.0)) throw std::invalid_argument("c_s / c_p must lie in (0, 1)");
  if (!(t_max > 0.0 && t_max < 1e9))
    throw std::invalid_argument("kernel table length must be in (0, 1e9)");
  const ModeStiffness k0 = static_stiffness(r);
  k0_11_ = k0.k11.real();
  k0_22_ = k0.k22.real();
  k0_12_ = k0.k12.real();
  build_nodes(t_max);

  // Table at T_j = j dT. cos/sin(w T_j) by rotation, re-seeded every 256 entries.
  const std::size_t count = std::size_t(std::ceil(t_max / table_step)) + 2;
  std::vector<double> s11(count, 0), s22(count, 0), c11(count, 0), c22(count, 0), c12(count, 0),
      s12(count, 0);
  for (const Node& n : band_) {
    const complex step = std::polar(1.0, n.w * table_step);
    complex z = 1.0;
    for (std::size_t j = 0; j < count; ++j) {
      if (j % 256 == 0) z = std::polar(1.0, n.w * double(j) * table_step);
      const double c = z.real(), s = z.imag();
      s11[j] += n.weight * n.re11 * s / n.w;
      s22[j] += n.weight * n.re22 * s / n.w;
      c11[j] += n.weight * n.re11 * c;
      c22[j] += n.weight * n.re22 * c;
      c12[j] += n.weight * n.im12 * (1.0 - c) / n.w;
      s12[j] += n.weight * n.im12 * s;
      z *= step;
    }
  }
  table_.resize(count);
  const double f = 2.0 / pi;
  for (std::size_t j = 0; j < count; ++j) {
    KernelValues& v = table_[j];
    v.g11 = k0_11_ - f * s11[j];
    v.g22 = k0_22_ - f * s22[j];
    v.g12 = k0_12_ - coupling_at_infinity() + f * c12[j];
    v.h11 = f * c11[j];
    v.h22 = f * c22[j];
    v.h12 = -f * s12[j];
  }
}

void HalfSpaceKernels::build_nodes(double t_max) {
  // Panel [0, 1]: w = sin(theta) makes b = sqrt(1 - w^2) = cos(theta) smooth at w = 1.
  // Panel [1, 1/r]: w = 1 + (1/r - 1) sin^2(phi/2) makes sqrt(w^2 - 1) and
  // sqrt(1 - r^2 w^2) smooth at both ends. Sub-panels keep w T within ~8 rad per panel.
  const double r = r_, r2 = r * r, span = 1.0 / r - 1.0;
  // Counted in double, and checked before they become integers (api/run_bounds.cpp keeps a
  // job's c_p / c_s <= 100, some 30 000 panels at the longest table).
  const double panel_counts[2] = {2.0 + std::ceil(0.5 * pi * t_max / 8.0),
                                  2.0 + std::ceil(pi * 0.5 * span * t_max / 8.0)};
  for (double count : panel_counts)
    if (!(count <= 1e7))
      throw std::invalid_argument("the kernel quadrature would need " + std::to_string(count) +
                                  " panels (c_p / c_s or the table length too large)");
  const int panels1 = int(panel_counts[0]), panels2 = int(panel_counts[1]);
  for (int m = 0; m < panels1; ++m) {
    const double lo = 0.5 * pi * m / panels1, hi = 0.5 * pi * (m + 1) / panels1;
    gauss_legendre_20(lo, hi, [&](double theta, double weight) {
      const double w = std::sin(theta), b = std::cos(theta);
      const double a = std::sqrt(1.0 - r2 * w * w);
      const double q = 1.0 + r2 - r2 * w * w;
      band_.push_back({w, weight * b, -a * (1.0 + a * b) / q, -b * (1.0 + a * b) / q, 0.0});
    });
  }
  for (int m = 0; m < panels2; ++m) {
    const double lo = pi * m / panels2, hi = pi * (m + 1) / panels2;
    gauss_legendre_20(lo, hi, [&](double phi, double weight) {
      const double sh = std::sin(0.5 * phi), ch = std::cos(0.5 * phi);
      const double w = 1.0 + span * sh * sh;
      const double big_b = sh * std::sqrt(span * (w + 1.0));      // sqrt(w^2 - 1)
      const double a = ch * std::sqrt((1.0 - r) * (1.0 + r * w)); // sqrt(1 - r^2 w^2)
      const double q = 1.0 + r2 - r2 * w * w;
      const double dw = 0.5 * span * std::sin(phi);
      // On 1 < w < 1/r: a real, b = i B: K11 = -a (1 + i a B)/Q, K22 = -i B (1 + i a B)/Q,
      // K12 = 2 - (1 + i a B)/Q.
      band_.push_back({w, weight * dw, -a / q, a * big_b * big_b / q, -a * big_b / q});
    });
  }
}

KernelValues HalfSpaceKernels::exact(double T) const {
  double s11 = 0, s22 = 0, c11 = 0, c22 = 0, c12 = 0, s12 = 0;
  for (const Node& n : band_) {
    const double c = std::cos(n.w * T), s = std::sin(n.w * T);
    s11 += n.weight * n.re11 * s / n.w;
    s22 += n.weight * n.re22 * s / n.w;
    c11 += n.weight * n.re11 * c;
    c22 += n.weight * n.re22 * c;
    c12 += n.weight * n.im12 * (1.0 - c) / n.w;
    s12 += n.weight * n.im12 * s;
  }
  const double f = 2.0 / pi;
  return {k0_11_ - f * s11, k0_22_ - f * s22, k0_12_ - coupling_at_infinity() + f * c12,
          f * c11,          f * c22,          -f * s12};
}

KernelValues HalfSpaceKernels::operator()(double T) const {
  const double x = std::clamp(T, 0.0, t_max_) / table_step;
  const std::size_t j = std::min(std::size_t(x), table_.size() - 2);
  const double s = x - double(j);
  const KernelValues &a = table_[j], &b = table_[j + 1];
  const double d = table_step; // slopes per unit s: dg/ds = -h dT
  return {hermite(s, a.g11, b.g11, -a.h11 * d, -b.h11 * d),
          hermite(s, a.g22, b.g22, -a.h22 * d, -b.h22 * d),
          hermite(s, a.g12, b.g12, -a.h12 * d, -b.h12 * d),
          0.0,
          0.0,
          0.0};
}

KernelValues HalfSpaceKernels::integral(double T0, double T1) const {
  // 4-point Gauss-Legendre on [T0, T1].
  static constexpr double x[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                  0.8611363115940526};
  static constexpr double w[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                  0.3478548451374538};
  const double half = 0.5 * (T1 - T0), mid = 0.5 * (T1 + T0);
  KernelValues sum;
  for (int i = 0; i < 4; ++i) {
    const KernelValues v = (*this)(mid + half * x[i]);
    sum.g11 += w[i] * half * v.g11;
    sum.g22 += w[i] * half * v.g22;
    sum.g12 += w[i] * half * v.g12;
  }
  return sum;
}

} // namespace slipfront::spectral
