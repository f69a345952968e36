// The experimentalist's procedure of paper Sec. 6 on one record (docs/length-fit.md):
// 1. fit the simplified Prakash-Clifton law: the measured length L_m (law_fit.hpp);
// 2. the measured critical frequency f_m from L_c(f_m) = L_m, by the attenuation rule of the
//    studies (A/A0 = 0.98 at the record's peak |V|: solver/run/critical_length_estimate.hpp);
// 3. the power spectrum of the record's contact pressure (record_spectrum.hpp);
// 4. the verdict: the event is rich enough (L_m is the interface's physical length) when more
//    than 1 % of that power lies above f_m, else L_m is only an upper bound.
#pragma once

#include "api/length_fit/interface_record.hpp"
#include "api/length_fit/law_fit.hpp"
#include "api/length_fit/record_checks.hpp"
#include "api/length_fit/record_spectrum.hpp"

#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// V* of the paper's runs (Fig. 2): the default when a request gives none.
inline constexpr double paper_v_star = 1e-4;

struct LengthFitOptions {
  std::optional<double> v_star; // [m/s]; paper_v_star when absent
  bool fit_v_star = false;
  std::optional<double> mu;             // fitted when absent
  std::optional<double> station_x1;     // which station of a stations CSV
  std::optional<double> slip_threshold; // [m/s]; 1 % of the peak |V| when absent
};

struct LengthFitVerdict {
  bool rich_enough = false;
  double power_above_f_m = 0; // fraction of the spectrum's power above f_m
  double power_threshold = 0; // 1 - spectral_power_fraction: 0.01
  double event_critical_length =
      0;                   // L_c of the event: the rule at the spectrum's 99 % frequency [m]
  double upper_bound = 0;  // when not rich: max(L_m, the event's L_c) [m]
  bool borderline = false; // the 95 % interval of L_m holds the event's L_c
  std::string text;        // the verdict in the paper's words
  std::string reason;      // the numbers that decided
};

struct LengthFit {
  SlippingSamples slipping;
  double peak_slip_rate = 0; // [m/s]
  LawFit fit;
  double critical_frequency = 0; // f_m [Hz]
  RecordSpectrum spectrum;
  LengthFitVerdict verdict;
};

struct LengthFitOutcome {
  std::optional<LengthFit> result;
  std::vector<RecordError> errors; // the record's (check_record), when there is no result
};

LengthFitOutcome fit_length(const InterfaceRecord& record, const LengthFitOptions& options);

} // namespace slipfront::api
