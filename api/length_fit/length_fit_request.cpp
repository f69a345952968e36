#include "api/length_fit/length_fit_request.hpp"

#include "api/json_fields.hpp"
#include "api/length_fit/length_fit_json.hpp"
#include "api/length_fit/record_reader.hpp"

namespace slipfront::api {

namespace {

constexpr const char* record_pointer = "/record";

} // namespace

const Interval& option_range(std::string_view name) {
  static const Interval v_star = left_open(0.0, 1e6), mu = left_open(0.0, 100.0),
                        station = any_finite(), threshold = closed_interval(0.0, 1e6);
  if (name == "v_star") return v_star;
  if (name == "mu") return mu;
  if (name == "slip_threshold") return threshold;
  return station;
}

LengthFitRequest parse_length_fit_request(const nlohmann::json& body) {
  LengthFitRequest out;
  if (!body.is_object()) {
    out.errors.push_back(
        {"", "the body must be a JSON object with a \"record\", got " + describe_value(body)});
    return out;
  }
  ObjectReader reader(&body, "", out.errors);
  LengthFitOptions& o = out.options;
  reader.optional_number("v_star", o.v_star, option_range("v_star"));
  reader.boolean("fit_v_star", o.fit_v_star);
  reader.optional_number("mu", o.mu, option_range("mu"));
  reader.optional_number("station_x1", o.station_x1, option_range("station_x1"));
  reader.optional_number("slip_threshold", o.slip_threshold, option_range("slip_threshold"));
  const nlohmann::json* record = reader.raw("record");
  reader.finish();
  if (record == nullptr) {
    out.errors.push_back({record_pointer, "missing: the record, an object of columns {\"time\": "
                                          "[...], \"slip_rate\": [...], \"contact_pressure\": "
                                          "[...], \"frictional_stress\": [...]} or CSV text"});
    return out;
  }
  RecordRead read;
  RecordSource::Kind kind = RecordSource::Kind::json;
  if (record->is_string()) {
    kind = RecordSource::Kind::csv;
    read = read_record_csv(record->get_ref<const std::string&>(), o.station_x1);
  } else if (record->is_object()) {
    read = read_record_json(*record);
    if (o.station_x1 && read.errors.empty())
      out.errors.push_back({"/station_x1", "a record of columns is one point: leave the "
                                           "station out"});
  } else {
    out.errors.push_back({record_pointer, "must be an object of columns or CSV text, got " +
                                              describe_value(*record)});
    return out;
  }
  for (const RecordError& e : read.errors)
    out.errors.push_back(to_field_error(e, kind, record_pointer));
  if (out.errors.empty()) out.record = std::move(read.record);
  return out;
}

LengthFitAnswer answer_length_fit(const InterfaceRecord& record, const LengthFitOptions& options) {
  LengthFitAnswer out;
  const LengthFitOutcome outcome = fit_length(record, options);
  for (const RecordError& e : outcome.errors)
    out.errors.push_back(to_field_error(e, record.source.kind, record_pointer));
  if (outcome.result) out.body = length_fit_json(record, *outcome.result);
  return out;
}

} // namespace slipfront::api
