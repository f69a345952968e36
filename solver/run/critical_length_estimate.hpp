// The spectral estimate of the critical length
// (docs/metrics.md "Spectral estimate of the critical length"): the paper's filter law
// (eq. 6), the frequency content of the strength record at the spectrum probe, and the
// estimate derived from both at the end of a run.
#pragma once

#include "solver/params.hpp"
#include "solver/run/metrics.hpp"
#include "solver/run/records.hpp"

#include <vector>

namespace slipfront {

// The rule's two numbers (docs/metrics.md): L_c keeps A/A0 >= 0.98 at the frequency below
// which 99 % of the record's power lies.
inline constexpr double critical_attenuation_ratio = 0.98;
inline constexpr double spectral_power_fraction = 0.99;

// The filter law of the paper (eq. 6): A/A0 = 1/sqrt(1 + (2 pi f L / (V* + |V|))^2).
double filter_amplitude_ratio(double frequency, double L, double v_star, double slip_velocity);

// Largest L for which A/A0 >= ratio at frequency f (inverse of the filter law).
double filter_critical_length(double frequency, double v_star, double slip_velocity,
                              double ratio = critical_attenuation_ratio);

// Highest frequency at which a filter of length L keeps A/A0 >= ratio: the same rule solved
// for f (L_c(f_m) = L, paper Sec. 6).
double filter_critical_frequency(double L, double v_star, double slip_velocity,
                                 double ratio = critical_attenuation_ratio);

// The one-sided power spectrum of a record (uniform steps dt) as the spectral estimate reads
// it: the straight line through the end points removed, a Hann window applied;
// power[k] = |X_k|^2 at frequency[k] = k / (n dt), k = 1 .. n/2 (DC excluded).
struct PowerSpectrum {
  std::vector<double> frequency; // [Hz]
  std::vector<double> power;     // [signal unit^2], unnormalised
};
PowerSpectrum detrended_power_spectrum(const std::vector<double>& signal, double dt);

// The frequency below which `fraction` of the spectrum's power lies (the first bin where the
// cumulative power reaches it); NaN when the total power is 0 (or the spectrum empty).
double cutoff_frequency(const PowerSpectrum& spectrum, double fraction = spectral_power_fraction);

// Frequency content of a strength record tau_s(t) (uniform steps): the frequency below which
// `fraction` of the power of the detrended, Hann-windowed signal lies (DC excluded); NaN for
// fewer than 16 samples.
double spectral_cutoff_frequency(const std::vector<double>& signal, double dt,
                                 double fraction = spectral_power_fraction);

// The spectral estimate of L_c (paper eq. 6) from the strength record at the spectrum probe,
// from half a second before the front arrives there to the end (NaN when undefined).
void derive_spectral_estimate(const SimulationParams& p, const FrontProfile& front,
                              const ProbeRecords& probes, double dx, double dt, Metrics& m);

} // namespace slipfront
