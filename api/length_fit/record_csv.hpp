// A record read from CSV text (docs/length-fit.md "The record"): a header naming the
// columns time, slip_rate, contact_pressure, frictional_stress (others are ignored), or the
// stations CSV of `slipfront stations --csv` as it is (station_x1, time, slip_rate,
// shear_traction, normal_traction: the pressure is -normal_traction), one station of it.
// Lines starting with '#' and blank lines are skipped; "\r\n" line ends are accepted.
#pragma once

#include "api/length_fit/interface_record.hpp"

#include <optional>
#include <string_view>
#include <vector>

namespace slipfront::api {

struct RecordRead {
  std::optional<InterfaceRecord> record; // set when there is no error
  std::vector<RecordError> errors;       // each with its line and column
};

// At most this many errors are reported; reading stops at the next one.
inline constexpr std::size_t max_record_errors = 10;

// The error of a record text larger than max_record_bytes, if it is.
std::optional<RecordError> size_error(std::string_view text);

// `station_x1`: the station to read from a CSV with a station_x1 column (needed when it holds
// more than one station). Checks the shape and the numbers (every cell read is a finite
// number), not the physics (check_record).
RecordRead read_record_csv(std::string_view text, std::optional<double> station_x1);

} // namespace slipfront::api
