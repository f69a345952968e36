// The body of POST /api/v1/length-fits (docs/length-fit.md "Worked example"): the record, as an
// object of columns or as CSV text, and the options v_star, fit_v_star, mu, station_x1,
// slip_threshold, each range-checked; errors name the field by JSON pointer, a CSV cell by
// its line and column.
#pragma once

#include "api/job_spec.hpp"
#include "api/json_fields.hpp"
#include "api/length_fit/length_fit.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string_view>
#include <vector>

namespace slipfront::api {

// The allowed range of the numeric option `name` (v_star, mu, station_x1, slip_threshold):
// the request and `slipfront fit-length` check the same.
const Interval& option_range(std::string_view name);

struct LengthFitRequest {
  std::optional<InterfaceRecord> record; // set when there is no error
  LengthFitOptions options;
  std::vector<FieldError> errors;
};

LengthFitRequest parse_length_fit_request(const nlohmann::json& body);

// The checks and the fit of a parsed request: the answer's JSON, or the record's errors as
// field errors of the request (pointer /record...).
struct LengthFitAnswer {
  nlohmann::json body;
  std::vector<FieldError> errors;
};
LengthFitAnswer answer_length_fit(const InterfaceRecord& record, const LengthFitOptions& options);

} // namespace slipfront::api
