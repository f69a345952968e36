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

// The filter law of the paper (eq. 6): A/A0 = 1/sqrt(1 + (2 pi f L / (V* + |V|))^2).
double filter_amplitude_ratio(double frequency, double L, double v_star, double slip_velocity);

// Largest L for which A/A0 >= ratio at frequency f (inverse of the filter law).
double filter_critical_length(double frequency, double v_star, double slip_velocity,
                              double ratio = 0.98);

// Frequency content of a strength record tau_s(t) (uniform steps): the frequency below which
// `fraction` of the power of the detrended, Hann-windowed signal lies (DC excluded).
double spectral_cutoff_frequency(const std::vector<double>& signal, double dt,
                                 double fraction = 0.99);

// The spectral estimate of L_c (paper eq. 6) from the strength record at the spectrum probe,
// from half a second before the front arrives there to the end (NaN when undefined).
void derive_spectral_estimate(const SimulationParams& p, const FrontProfile& front,
                              const ProbeRecords& probes, double dx, double dt, Metrics& m);

} // namespace slipfront
