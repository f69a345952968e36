#include "api/length_fit/record_checks.hpp"

#include "api/number_text.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::api {

namespace {

double peak_abs(const std::vector<double>& values) {
  double peak = 0;
  for (double v : values)
    peak = std::max(peak, std::abs(v));
  return peak;
}

RecordError column_error(const InterfaceRecord& record, RecordColumn column, std::string reason) {
  return {record.source.column_names[std::size_t(column)], -1, 0, std::move(reason)};
}

} // namespace

SlippingSamples slipping_samples(const InterfaceRecord& record,
                                 std::optional<double> slip_threshold) {
  SlippingSamples out;
  out.threshold =
      slip_threshold.value_or(default_slip_threshold_fraction * peak_abs(record.slip_rate));
  out.slipping.resize(record.size());
  for (std::size_t k = 0; k < record.size(); ++k) {
    const double v = std::abs(record.slip_rate[k]);
    out.slipping[k] = v > 0 && v >= out.threshold;
    out.count += std::size_t(out.slipping[k]);
  }
  return out;
}

std::vector<RecordError> check_record(const InterfaceRecord& record,
                                      std::optional<double> slip_threshold) {
  std::vector<RecordError> errors;
  const std::size_t n = record.size();
  if (n < min_record_points) {
    errors.push_back({"", -1, 0,
                      "too short: " + std::to_string(n) + " samples, a fit needs at least " +
                          std::to_string(min_record_points)});
    return errors;
  }
  for (std::size_t c = 0; c < record_column_count; ++c) {
    const auto column = RecordColumn(c);
    const std::vector<double>& values = record.column(column);
    if (values.size() != n) {
      errors.push_back(column_error(record, column,
                                    "has " + std::to_string(values.size()) + " values, time has " +
                                        std::to_string(n)));
      return errors;
    }
    const auto bad = std::find_if(values.begin(), values.end(),
                                  [](double v) { return !(std::abs(v) <= max_record_magnitude); });
    if (bad != values.end())
      errors.push_back(error_at(record, column, std::size_t(bad - values.begin()),
                                "must be a finite number within +-" +
                                    number_text(max_record_magnitude) + ", got " +
                                    number_text(*bad)));
  }
  if (!errors.empty()) return errors;
  for (std::size_t k = 1; k < n; ++k) {
    if (!(record.time[k] > record.time[k - 1])) {
      errors.push_back(
          error_at(record, RecordColumn::time, k,
                   "time must increase from sample to sample: " + number_text(record.time[k], 12) +
                       " s follows " + number_text(record.time[k - 1], 12) + " s"));
      break;
    }
  }
  // The law's input is the Coulomb strength mu max(0, p) (paper eq. 1): it must be positive
  // somewhere and vary, or every L gives the same strength.
  double p_min = INFINITY, p_max = -INFINITY;
  for (double p : record.contact_pressure) {
    p_min = std::min(p_min, std::max(0.0, p));
    p_max = std::max(p_max, std::max(0.0, p));
  }
  if (!(p_max > 0))
    errors.push_back(column_error(record, RecordColumn::contact_pressure,
                                  "no contact: the pressure is never > 0 (compression is "
                                  "positive), so the law's strength mu max(0, p) is 0 throughout"));
  else if (!(p_max > p_min))
    errors.push_back(column_error(record, RecordColumn::contact_pressure,
                                  "the pressure never changes: the law's strength is mu p for "
                                  "every L, so there is no length to fit"));
  if (peak_abs(record.slip_rate) == 0) {
    errors.push_back(column_error(record, RecordColumn::slip_rate,
                                  "no slip: the slip rate is 0 in every sample"));
    return errors;
  }
  const SlippingSamples slip = slipping_samples(record, slip_threshold);
  if (slip.count < min_slipping_points) {
    errors.push_back(
        column_error(record, RecordColumn::slip_rate,
                     "too little slip: " + std::to_string(slip.count) +
                         " samples have |slip rate| >= " + number_text(slip.threshold) +
                         " m/s, a fit needs at least " + std::to_string(min_slipping_points)));
    return errors;
  }
  double stress = 0;
  for (std::size_t k = 0; k < n; ++k)
    if (slip.slipping[k]) stress = std::max(stress, std::abs(record.frictional_stress[k]));
  if (!(stress > 0))
    errors.push_back(column_error(record, RecordColumn::frictional_stress,
                                  "the stress is 0 wherever the interface slips: nothing to fit"));
  return errors;
}

} // namespace slipfront::api
