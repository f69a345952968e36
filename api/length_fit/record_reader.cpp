#include "api/length_fit/record_reader.hpp"

#include "api/json_fields.hpp"
#include "api/json_parse.hpp"

namespace slipfront::api {

namespace {

// A JSON pointer "/a/b/3" relative to the record as a RecordError (column a, index from the
// last segment when it is a number).
RecordError json_error(const FieldError& field) {
  RecordError e;
  e.reason = field.reason;
  std::string_view rest(field.pointer);
  if (rest.starts_with("/")) rest.remove_prefix(1);
  const std::size_t slash = rest.find('/');
  e.column = std::string(rest.substr(0, slash));
  if (slash != std::string_view::npos) {
    const std::string_view index = rest.substr(slash + 1);
    if (!index.empty() && index.find_first_not_of("0123456789") == std::string_view::npos &&
        index.size() < 10)
      e.index = std::stol(std::string(index));
  }
  return e;
}

} // namespace

RecordRead read_record_json(const nlohmann::json& json) {
  RecordRead out;
  if (!json.is_object()) {
    out.errors.push_back({"", -1, 0,
                          "the record must be an object of columns (time, slip_rate, "
                          "contact_pressure, frictional_stress), got " +
                              describe_value(json)});
    return out;
  }
  std::vector<FieldError> errors;
  InterfaceRecord record;
  record.source.kind = RecordSource::Kind::json;
  ObjectReader reader(&json, "", errors);
  for (std::size_t c = 0; c < record_column_count; ++c) {
    const std::string name = column_name(RecordColumn(c));
    if (reader.raw(name) == nullptr)
      reader.error(name, "missing: a record has the columns time, slip_rate, contact_pressure "
                         "and frictional_stress");
    else
      reader.number_list(name, record.column(RecordColumn(c)), max_record_points, any_finite());
  }
  reader.finish();
  if (errors.empty()) {
    for (std::size_t c = 1; c < record_column_count; ++c) {
      const auto column = RecordColumn(c);
      if (record.column(column).size() != record.time.size())
        errors.push_back({std::string("/").append(column_name(column)),
                          "has " + std::to_string(record.column(column).size()) +
                              " values, time has " + std::to_string(record.time.size())});
    }
  }
  for (std::size_t i = 0; i < errors.size() && i < max_record_errors; ++i)
    out.errors.push_back(json_error(errors[i]));
  if (out.errors.empty()) out.record = std::move(record);
  return out;
}

RecordRead read_record_text(std::string_view text, std::optional<double> station_x1) {
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos || text[first] != '{')
    return read_record_csv(text, station_x1);
  RecordRead out;
  if (auto too_large = size_error(text)) {
    out.errors.push_back(*too_large);
    return out;
  }
  const JsonParse parsed = parse_bounded_json(text);
  if (!parsed.ok()) {
    out.errors.push_back(json_error(parsed.error));
    return out;
  }
  if (station_x1) {
    out.errors.push_back(
        {"station_x1", -1, 0, "a JSON record is one point: leave the station out"});
    return out;
  }
  return read_record_json(parsed.value);
}

FieldError to_field_error(const RecordError& e, RecordSource::Kind kind,
                          const std::string& pointer) {
  if (e.column == "station_x1" && e.line == 0) return {"/station_x1", e.reason};
  if (kind != RecordSource::Kind::json || e.column.empty()) return {pointer, describe(e)};
  std::string at = pointer; // appended piece by piece: see describe()
  at.append("/").append(e.column);
  if (e.index >= 0) at.append("/").append(std::to_string(e.index));
  return {at, e.reason};
}

} // namespace slipfront::api
