// The power spectrum of a record's contact pressure, the input the law filters (paper eq. 6;
// docs/length-fit.md "f_m, the spectrum and the verdict"): on the record's own samples when
// they are evenly spaced, else on an even grid by linear interpolation; detrended,
// Hann-windowed and read as the spectral estimate of the studies reads tau_s
// (solver/run/critical_length_estimate.hpp).
#pragma once

#include "api/length_fit/interface_record.hpp"
#include "solver/run/critical_length_estimate.hpp"

#include <cstddef>

namespace slipfront::api {

// An uneven record is resampled onto at most this many points (and 4 per sample).
inline constexpr std::size_t max_spectrum_points = std::size_t{1} << 21;

struct RecordSpectrum {
  double sample_interval = 0; // [s] of the samples transformed
  std::size_t samples = 0;
  bool resampled = false; // the record's samples were uneven
  // power[k]: the fraction of the total power (DC excluded) in the bin at frequency[k].
  PowerSpectrum spectrum;
  double frequency_99 = 0; // below which spectral_power_fraction of the power lies [Hz]

  // The fraction of the power in the bins above f.
  double power_above(double f) const;
};

RecordSpectrum contact_pressure_spectrum(const InterfaceRecord& record);

} // namespace slipfront::api
