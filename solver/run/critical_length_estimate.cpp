#include "solver/run/critical_length_estimate.hpp"

#include "solver/interface/friction/regularization_law.hpp"
#include "solver/run/periodic_line.hpp"

#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

namespace slipfront {

double filter_amplitude_ratio(double frequency, double L, double v_star, double slip_velocity) {
  const double r = 2.0 * std::numbers::pi * frequency * L / (v_star + std::abs(slip_velocity));
  return 1.0 / std::sqrt(1.0 + r * r);
}

double filter_critical_length(double frequency, double v_star, double slip_velocity, double ratio) {
  // 1 / sqrt(1 + r^2) = ratio  <=>  r = sqrt(1/ratio^2 - 1), r = 2 pi f L / (V* + |V|).
  const double r = std::sqrt(1.0 / (ratio * ratio) - 1.0);
  return r * (v_star + std::abs(slip_velocity)) / (2.0 * std::numbers::pi * frequency);
}

double filter_critical_frequency(double L, double v_star, double slip_velocity, double ratio) {
  // r = 2 pi f L / (V* + |V|) is symmetric in f and L: the inverse for f is the same formula.
  return filter_critical_length(L, v_star, slip_velocity, ratio);
}

PowerSpectrum detrended_power_spectrum(const std::vector<double>& signal, double dt) {
  const std::size_t n = signal.size();
  PowerSpectrum out;
  if (n < 2) return out;
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
  out.frequency.reserve(half);
  out.power.reserve(half);
  for (std::size_t k = 1; k <= half; ++k) {
    out.frequency.push_back(double(k) / (double(n) * dt));
    out.power.push_back(std::norm(spectrum[k]));
  }
  return out;
}

double cutoff_frequency(const PowerSpectrum& spectrum, double fraction) {
  double total = 0;
  for (double p : spectrum.power)
    total += p;
  if (total <= 0) return std::numeric_limits<double>::quiet_NaN();
  double cumulative = 0;
  for (std::size_t k = 0; k < spectrum.power.size(); ++k) {
    cumulative += spectrum.power[k];
    if (cumulative >= fraction * total) return spectrum.frequency[k];
  }
  return spectrum.frequency.back();
}

double spectral_cutoff_frequency(const std::vector<double>& signal, double dt, double fraction) {
  if (signal.size() < 16) return std::numeric_limits<double>::quiet_NaN();
  return cutoff_frequency(detrended_power_spectrum(signal, dt), fraction);
}

void derive_spectral_estimate(const SimulationParams& p, const FrontProfile& front,
                              const ProbeRecords& probes, double dx, double dt, Metrics& m) {
  // The strength record at the spectrum probe from half a second before the front arrives
  // to the end; |V| = the peak slip speed there (docs/metrics.md).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  m.spectral_frequency = m.spectral_velocity = m.spectral_critical_length = nan;
  // The filter law of the slip-scale regularisation with a constant coefficient (the paper's).
  if (!coefficient_law(p.friction).constant() ||
      !effective_regularization(p.friction).slip_filter())
    return;
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

} // namespace slipfront
