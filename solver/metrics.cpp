#include "solver/metrics.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace slipfront {

const char* to_string(Outcome outcome) {
  switch (outcome) {
  case Outcome::arrested:
    return "arrested";
  case Outcome::running_at_end:
    return "running_at_end";
  case Outcome::no_rupture:
    return "no_rupture";
  case Outcome::diverged:
    return "diverged";
  }
  return "unknown";
}

std::vector<double> rupture_speed_profile(const std::vector<double>& x1,
                                          const std::vector<double>& arrival_time,
                                          double half_window) {
  // V_r = 1 / (d t_front / d x1), the slope from a least-squares line through the arrival
  // times of the nodes within +- half_window (a smoothing, centred derivative).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int n = int(x1.size());
  std::vector<double> speed(n, nan);
  for (int i = 0; i < n; ++i) {
    if (std::isnan(arrival_time[i])) continue;
    double sx = 0, st = 0, sxx = 0, sxt = 0;
    int count = 0;
    for (int k = i - 1; k >= 0 && x1[i] - x1[k] <= half_window && !std::isnan(arrival_time[k]);
         --k) {
      sx += x1[k], st += arrival_time[k], sxx += x1[k] * x1[k], sxt += x1[k] * arrival_time[k];
      ++count;
    }
    for (int k = i; k < n && x1[k] - x1[i] <= half_window && !std::isnan(arrival_time[k]); ++k) {
      sx += x1[k], st += arrival_time[k], sxx += x1[k] * x1[k], sxt += x1[k] * arrival_time[k];
      ++count;
    }
    if (count < 3) continue;
    const double slope = (count * sxt - sx * st) / (count * sxx - sx * sx); // dt/dx1
    if (slope > 0) speed[i] = 1.0 / slope;
  }
  return speed;
}

double filter_amplitude_ratio(double frequency, double L, double v_star, double slip_velocity) {
  const double r = 2.0 * std::numbers::pi * frequency * L / (v_star + std::abs(slip_velocity));
  return 1.0 / std::sqrt(1.0 + r * r);
}

double filter_critical_length(double frequency, double v_star, double slip_velocity, double ratio) {
  // 1 / sqrt(1 + r^2) = ratio  <=>  r = sqrt(1/ratio^2 - 1), r = 2 pi f L / (V* + |V|).
  const double r = std::sqrt(1.0 / (ratio * ratio) - 1.0);
  return r * (v_star + std::abs(slip_velocity)) / (2.0 * std::numbers::pi * frequency);
}

RupturedStretch ruptured_stretch(const std::vector<double>& x1,
                                 const std::vector<double>& arrival_time, double patch_lo,
                                 double patch_hi, double width) {
  RupturedStretch out;
  const int n = int(x1.size());
  auto slipped = [&](int i) { return !std::isnan(arrival_time[((i % n) + n) % n]); };
  // Seed: the earliest node that slipped inside the nucleation patch, else the earliest
  // node anywhere.
  int seed = -1;
  for (int pass = 0; pass < 2 && seed < 0; ++pass)
    for (int i = 0; i < n; ++i) {
      if (!slipped(i)) continue;
      if (pass == 0 && (x1[i] < patch_lo || x1[i] > patch_hi)) continue;
      if (seed < 0 || arrival_time[i] < arrival_time[seed]) seed = i;
    }
  if (seed < 0) return out;
  out.any_slip = true;
  int lo = seed, hi = seed;
  while (hi - lo + 1 < n && slipped(lo - 1))
    --lo;
  while (hi - lo + 1 < n && slipped(hi + 1))
    ++hi;
  const double dx = width / n;
  auto unwrapped_x = [&](int i) {
    return x1[((i % n) + n) % n] + std::floor(double(i) / n) * width;
  };
  out.left = unwrapped_x(lo);
  out.right = unwrapped_x(hi);
  for (int i = lo; i <= hi; ++i)
    out.nodes.push_back(((i % n) + n) % n);
  out.ruptured = out.left < patch_lo - 0.5 * dx || out.right > patch_hi + 0.5 * dx;
  return out;
}

double spectral_cutoff_frequency(const std::vector<double>& signal, double dt, double fraction) {
  const std::size_t n = signal.size();
  if (n < 16) return std::numeric_limits<double>::quiet_NaN();
  // Remove the straight line through the end points (a step would otherwise leak power to
  // every frequency through the periodic extension), then apply a Hann window.
  std::vector<double> x(n);
  const double a = signal.front(), b = signal.back();
  for (std::size_t k = 0; k < n; ++k) {
    const double s = double(k) / double(n - 1);
    const double hann = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * s);
    x[k] = (signal[k] - (a + (b - a) * s)) * hann;
  }
  Eigen::FFT<double> fft;
  std::vector<std::complex<double>> spectrum;
  fft.fwd(spectrum, x);
  const std::size_t half = n / 2;
  double total = 0;
  for (std::size_t k = 1; k <= half; ++k)
    total += std::norm(spectrum[k]);
  if (total <= 0) return std::numeric_limits<double>::quiet_NaN();
  double cumulative = 0;
  for (std::size_t k = 1; k <= half; ++k) {
    cumulative += std::norm(spectrum[k]);
    if (cumulative >= fraction * total) return double(k) / (double(n) * dt);
  }
  return double(half) / (double(n) * dt);
}

} // namespace slipfront
