#include "api/length_fit/length_fit.hpp"

#include "api/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront::api {

namespace {

std::string percent(double fraction) {
  return number_text(100 * fraction, 3) + " %";
}

LengthFitVerdict decide(const LengthFit& r) {
  LengthFitVerdict v;
  const double L_m = r.fit.law.L;
  v.power_threshold = 1.0 - spectral_power_fraction;
  v.power_above_f_m = r.spectrum.power_above(r.critical_frequency);
  v.event_critical_length =
      filter_critical_length(r.spectrum.frequency_99, r.fit.law.v_star, r.peak_slip_rate);
  v.rich_enough = v.power_above_f_m > v.power_threshold;
  v.borderline = r.fit.L_low <= v.event_critical_length && v.event_critical_length <= r.fit.L_high;
  const std::string numbers =
      percent(v.power_above_f_m) +
      " of the contact pressure's power lies above f_m = " + number_text(r.critical_frequency, 3) +
      " Hz (the threshold is " + percent(v.power_threshold) +
      "); the event's critical length, the rule at its " +
      number_text(100 * spectral_power_fraction, 3) + " % power frequency " +
      number_text(r.spectrum.frequency_99, 3) + " Hz, is " +
      number_text(v.event_critical_length, 3) + " m, against L_m = " + number_text(L_m, 3) + " m";
  // Worded so that no number reads against another: when the event is not rich enough the
  // one bound is the largest length it names, and L_m is said to lie below it.
  if (v.rich_enough) {
    v.text = "the event is rich enough: the interface's physical length is L_m = " +
             number_text(L_m, 3) + " m";
    v.upper_bound = std::numeric_limits<double>::quiet_NaN();
  } else {
    v.upper_bound = std::max(L_m, v.event_critical_length);
    v.text = "the event is not rich enough to measure the length: the physical length is at "
             "most " +
             number_text(v.upper_bound, 3) +
             " m (this event's critical length: any shorter length "
             "changes its stresses by less than 2 %), and the "
             "fitted L_m = " +
             number_text(L_m, 3) +
             " m, below that bound, is not a measurement of it — a sharper "
             "event is needed";
  }
  v.reason = numbers;
  const std::vector<double>& f = r.spectrum.spectrum.frequency;
  if (!f.empty() && r.critical_frequency > f.back())
    v.reason += "; f_m lies above the highest frequency the record resolves (" +
                number_text(f.back(), 3) + " Hz, half its sampling rate)";
  if (v.borderline)
    v.reason += "; borderline: the 95 % interval of L_m [" + number_text(r.fit.L_low, 3) + ", " +
                number_text(r.fit.L_high, 3) + "] m holds the event's critical length";
  return v;
}

} // namespace

LengthFitOutcome fit_length(const InterfaceRecord& record, const LengthFitOptions& options) {
  LengthFitOutcome out;
  out.errors = check_record(record, options.slip_threshold);
  if (!out.errors.empty()) return out;
  LengthFit r;
  r.slipping = slipping_samples(record, options.slip_threshold);
  for (double v : record.slip_rate)
    r.peak_slip_rate = std::max(r.peak_slip_rate, std::abs(v));
  LawFitSettings settings;
  settings.v_star = options.v_star.value_or(paper_v_star);
  settings.fit_v_star = options.fit_v_star;
  settings.mu = options.mu;
  r.fit = fit_prakash_clifton(record, r.slipping, settings);
  // L_c(f_m) = L_m, at the weakest attenuation the record sees: its peak |V| (as the studies'
  // spectral estimate, docs/metrics.md).
  r.critical_frequency = filter_critical_frequency(r.fit.law.L, r.fit.law.v_star, r.peak_slip_rate);
  r.spectrum = contact_pressure_spectrum(record);
  r.verdict = decide(r);
  out.result = std::move(r);
  return out;
}

} // namespace slipfront::api
