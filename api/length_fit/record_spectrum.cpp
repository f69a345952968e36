#include "api/length_fit/record_spectrum.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::api {

double RecordSpectrum::power_above(double f) const {
  double above = 0;
  for (std::size_t k = 0; k < spectrum.frequency.size(); ++k)
    if (spectrum.frequency[k] > f) above += spectrum.power[k];
  return above;
}

RecordSpectrum contact_pressure_spectrum(const InterfaceRecord& record) {
  RecordSpectrum out;
  const std::size_t n = record.size();
  std::vector<double> steps(n - 1);
  for (std::size_t k = 1; k < n; ++k)
    steps[k - 1] = record.time[k] - record.time[k - 1];
  const double duration = record.time.back() - record.time.front();
  const double mean_step = duration / double(n - 1);
  const bool even = std::all_of(steps.begin(), steps.end(), [&](double h) {
    return std::abs(h - mean_step) <= 1e-6 * mean_step;
  });
  // The law's input: mu max(0, p); mu scales every bin alike and leaves the fractions.
  std::vector<double> signal;
  if (even) {
    out.sample_interval = mean_step;
    for (double p : record.contact_pressure)
      signal.push_back(std::max(0.0, p));
  } else {
    std::nth_element(steps.begin(), steps.begin() + long(steps.size() / 2), steps.end());
    const double cap = double(std::min(max_spectrum_points, 4 * n));
    const double wanted = std::floor(duration / steps[steps.size() / 2]) + 1; // may be huge
    const auto points = std::size_t(std::clamp(wanted, 2.0, cap));
    out.sample_interval = duration / double(points - 1);
    out.resampled = true;
    std::size_t k = 0;
    for (std::size_t i = 0; i < points; ++i) {
      const double t = std::min(record.time.back(), record.time.front() + i * out.sample_interval);
      while (k + 2 < n && record.time[k + 1] < t)
        ++k;
      const double w = (t - record.time[k]) / (record.time[k + 1] - record.time[k]);
      const double a = std::max(0.0, record.contact_pressure[k]);
      const double b = std::max(0.0, record.contact_pressure[k + 1]);
      signal.push_back(a + std::clamp(w, 0.0, 1.0) * (b - a));
    }
  }
  out.samples = signal.size();
  out.spectrum = detrended_power_spectrum(signal, out.sample_interval);
  double total = 0;
  for (double p : out.spectrum.power)
    total += p;
  if (total > 0)
    for (double& p : out.spectrum.power)
      p /= total;
  out.frequency_99 = cutoff_frequency(out.spectrum);
  return out;
}

} // namespace slipfront::api
