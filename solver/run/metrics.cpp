#include "solver/run/metrics.hpp"

#include "solver/interface/nucleation.hpp"
#include "solver/run/periodic_index.hpp"

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
  auto slipped = [&](int i) { return !std::isnan(arrival_time[periodic_index(i, n)]); };
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
    return x1[periodic_index(i, n)] + std::floor(double(i) / n) * width;
  };
  out.left = unwrapped_x(lo);
  out.right = unwrapped_x(hi);
  for (int i = lo; i <= hi; ++i)
    out.nodes.push_back(periodic_index(i, n));
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

int nearest_node(double x1, double x_min, double dx, int nx) {
  return periodic_index(std::lround((x1 - x_min) / dx), nx);
}

double interpolate_nodal(const std::vector<double>& values, double x1, double x_min, double dx) {
  const int nx = int(values.size());
  const double s = (x1 - x_min) / dx;
  const long i0 = long(std::floor(s));
  const double w = s - double(i0);
  auto at = [&](long i) { return values[periodic_index(i, nx)]; };
  if (w < 1e-9) return at(i0);
  return (1 - w) * at(i0) + w * at(i0 + 1);
}

void derive_front_metrics(const SimulationParams& p, double dx,
                          const std::vector<double>& arrival_time, FrontProfile& front,
                          Metrics& m) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int nx = int(arrival_time.size());
  const auto patch = p.nucleation.enabled ? nucleation_patch(p.nucleation)
                                          : Interval{std::numeric_limits<double>::infinity(),
                                                     -std::numeric_limits<double>::infinity()};
  front.x1.resize(nx);
  for (int i = 0; i < nx; ++i)
    front.x1[i] = p.geometry.x_min + i * dx;
  front.arrival_time = arrival_time;
  front.rupture_speed.assign(nx, nan);

  const RupturedStretch stretch =
      ruptured_stretch(front.x1, front.arrival_time, patch.lo, patch.hi, p.geometry.width);
  m.arrest_position = stretch.any_slip ? stretch.right : nan;
  m.propagation_distance = stretch.any_slip ? stretch.right - stretch.left : 0.0;
  m.probe_x1 = p.probes.arrival_x1;
  m.arrival_time_at_probe =
      interpolate_nodal(front.arrival_time, p.probes.arrival_x1, p.geometry.x_min, dx);

  // V_r along the stretch, on unwrapped positions; max and mean outside the nucleation patch
  // (inside it the nucleation, not the rupture, sets the front).
  std::vector<double> xs, ts;
  for (std::size_t k = 0; k < stretch.nodes.size(); ++k) {
    xs.push_back(stretch.left + double(k) * dx);
    ts.push_back(front.arrival_time[stretch.nodes[k]]);
  }
  const std::vector<double> vr = rupture_speed_profile(xs, ts, std::max(0.25, 2.0 * dx));
  double vmax = nan, vsum = 0;
  int count = 0;
  for (std::size_t k = 0; k < stretch.nodes.size(); ++k) {
    front.rupture_speed[stretch.nodes[k]] = vr[k];
    if (std::isnan(vr[k]) || (xs[k] >= patch.lo && xs[k] <= patch.hi)) continue;
    vmax = std::isnan(vmax) ? vr[k] : std::max(vmax, vr[k]);
    vsum += vr[k];
    ++count;
  }
  m.max_rupture_speed = vmax;
  m.mean_rupture_speed = count > 0 ? vsum / count : nan;
  if (m.outcome != Outcome::diverged && !stretch.ruptured) m.outcome = Outcome::no_rupture;
  if (stretch.nodes.size() == std::size_t(nx))
    m.warnings.push_back(
        "the whole periodic interface slipped: the rupture met itself across the seam");
}

void derive_spectral_estimate(const SimulationParams& p, const FrontProfile& front,
                              const ProbeRecords& probes, double dx, double dt, Metrics& m) {
  // The strength record at the spectrum probe from half a second before the front arrives
  // to the end; |V| = the peak slip speed there (docs/metrics.md).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.spectral_frequency = m.spectral_velocity = m.spectral_critical_length = nan;
  if (p.friction.law != FrictionLaw::prakash_clifton) return;
  const double arrival =
      interpolate_nodal(front.arrival_time, p.probes.spectrum_x1, p.geometry.x_min, dx);
  if (std::isnan(arrival)) return;
  std::vector<double> window;
  double vpeak = 0;
  for (std::size_t k = 0; k < probes.time.size(); ++k) {
    if (probes.time[k] < arrival - 0.5) continue;
    window.push_back(probes.strength_spectrum[k]);
    vpeak = std::max(vpeak, std::abs(probes.slip_velocity_spectrum[k]));
  }
  const double f = spectral_cutoff_frequency(window, dt);
  if (std::isnan(f)) return;
  m.spectral_frequency = f;
  m.spectral_velocity = vpeak;
  m.spectral_critical_length = filter_critical_length(f, p.friction.v_star, vpeak);
}

double energy_balance_error(const EnergyRecords& e) {
  // E - E(0) = W - D with E(0) = 0 (docs/physics.md).
  if (e.time.empty()) return 0.0;
  const std::size_t k = e.time.size() - 1;
  const double stored = e.kinetic[k] + e.strain[k];
  const double net = e.external_work[k] - e.dissipated[k];
  const double scale = std::max({std::abs(e.external_work[k]), std::abs(stored), 1e-300});
  return std::abs(stored - net) / scale;
}

} // namespace slipfront
