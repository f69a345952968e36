// A record from JSON ({"time": [...], "slip_rate": [...], "contact_pressure": [...],
// "frictional_stress": [...]}) or from text (JSON when it starts with '{', else CSV:
// record_csv.hpp), and its errors as the field errors of a request (a JSON pointer into the
// record; for a CSV the pointer of the text, the line and column in the reason).
#pragma once

#include "api/job_spec.hpp"
#include "api/length_fit/record_csv.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>
#include <vector>

namespace slipfront::api {

// The four columns as arrays of equal length (at most max_record_points finite numbers each);
// no other member. Errors name pointer + "/<column>[/<index>]".
RecordRead read_record_json(const nlohmann::json& record);

// JSON or CSV text (a file's content, a request's string).
RecordRead read_record_text(std::string_view text, std::optional<double> station_x1);

// `error` as a field error of the record at `pointer` ("/record" in a request).
FieldError to_field_error(const RecordError& error, RecordSource::Kind kind,
                          const std::string& pointer);

} // namespace slipfront::api
