// What a record must be before a length fit (docs/length-fit.md "The record"): long enough,
// finite, time strictly increasing, in contact with a pressure that varies, and slipping in
// enough samples; each error names the column and the sample.
#pragma once

#include "api/length_fit/interface_record.hpp"

#include <optional>
#include <vector>

namespace slipfront::api {

// The samples where the interface slips: |V| >= threshold, and threshold itself.
struct SlippingSamples {
  double threshold = 0;       // [m/s]
  std::vector<char> slipping; // one flag per sample
  std::size_t count = 0;
};

// The default threshold is 1 % of the record's peak |V| (docs/length-fit.md).
inline constexpr double default_slip_threshold_fraction = 0.01;
SlippingSamples slipping_samples(const InterfaceRecord& record,
                                 std::optional<double> slip_threshold);

// Every rule the record breaks (the first sample breaking each), none when it can be fitted.
std::vector<RecordError> check_record(const InterfaceRecord& record,
                                      std::optional<double> slip_threshold);

} // namespace slipfront::api
