#include "api/metrics_reader.hpp"

#include "api/json_fields.hpp" // child_pointer

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

namespace slipfront::api {

namespace {

using nlohmann::json;

// Why `value` is not what its name holds, or "" when it is.
using Check = std::function<std::string(const json& value)>;

constexpr std::size_t max_text_bytes = 4096;
constexpr std::size_t max_entries = 100000;

std::string number_or_null(const json& v) {
  if (v.is_null()) return "";
  if (!v.is_number() || !std::isfinite(v.get<double>())) return "must be a finite number or null";
  return "";
}

std::string whole_count(const json& v) {
  if (v.is_null()) return "";
  constexpr double largest = 9007199254740992.0; // 2^53: every whole number below is exact
  if (!v.is_number() || !(v.get<double>() >= 0.0 && v.get<double>() <= largest) ||
      std::floor(v.get<double>()) != v.get<double>())
    return "must be a whole number from 0 to 2^53 or null";
  return "";
}

std::string text(const json& v) {
  if (!v.is_string() || v.get_ref<const std::string&>().size() > max_text_bytes)
    return "must be a string of at most " + std::to_string(max_text_bytes) + " bytes";
  return "";
}

std::string boolean(const json& v) {
  return v.is_boolean() ? "" : "must be true or false";
}

// An object of at most `max_keys` members, each a number or null.
Check numbers_object(std::size_t max_keys) {
  return [max_keys](const json& v) -> std::string {
    if (!v.is_object() || v.size() > max_keys)
      return "must be an object of at most " + std::to_string(max_keys) + " numbers";
    for (const auto& [key, member] : v.items())
      if (!number_or_null(member).empty()) return "member " + key + " must be a number or null";
    return "";
  };
}

// An object whose members are the given names only, each a text or a number (or null):
// one entry of `provenance` or `job_warnings`.
Check record_of(std::vector<std::string> names) {
  return [names](const json& v) -> std::string {
    if (!v.is_object()) return "must be an object";
    for (const auto& [key, member] : v.items()) {
      if (std::find(names.begin(), names.end(), key) == names.end())
        return "has a member " + key + " that is not one of its names";
      if (!number_or_null(member).empty() && !text(member).empty())
        return "member " + key + " must be a text or a number";
    }
    return "";
  };
}

// A list of at most max_entries entries, each passing `entry`.
Check list_of(Check entry) {
  return [entry](const json& v) -> std::string {
    if (!v.is_array() || v.size() > max_entries)
      return "must be a list of at most " + std::to_string(max_entries) + " entries";
    for (std::size_t i = 0; i < v.size(); ++i)
      if (auto why = entry(v[i]); !why.empty()) return "entry " + std::to_string(i) + " " + why;
    return "";
  };
}

// Each name metrics_json() writes, with its check.
const std::map<std::string, Check>& checks() {
  static const std::map<std::string, Check> table = {
      {"front_threshold", number_or_null},
      {"arrest_position", number_or_null},
      {"propagation_distance", number_or_null},
      {"arrival_time_at_probe", number_or_null},
      {"probe_x1", number_or_null},
      {"rupture_speed", numbers_object(2)},
      {"max_slip_velocity", number_or_null},
      {"outcome", text},
      {"energy_error", number_or_null},
      {"wall_time_s", number_or_null},
      {"steps", whole_count},
      {"dt", number_or_null},
      {"stable_dt", number_or_null},
      {"simulated_time", number_or_null},
      {"spectral_critical_length", number_or_null},
      {"spectral_frequency", number_or_null},
      {"spectral_velocity", number_or_null},
      {"warnings", list_of(text)},
      {"message", text},
      {"cancelled", boolean},
      {"mesh", numbers_object(16)},
      {"stations", list_of(numbers_object(5))},
      {"code_version", text},
      {"method", text},
      {"method_description", text},
      // What the validation said about the job (api/run_job.cpp): its values with their
      // sources and its warnings.
      {"provenance", list_of(record_of({"pointer", "value", "unit", "source"}))},
      {"job_warnings", list_of(record_of({"pointer", "message"}))},
      // Older spellings of rupture_speed.max and .mean (api/metrics_row.cpp reads them).
      {"max_rupture_speed", number_or_null},
      {"mean_rupture_speed", number_or_null},
  };
  return table;
}

} // namespace

const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const auto& [name, check] : checks())
      out.push_back(name);
    return out;
  }();
  return names;
}

MetricsRead read_metrics(const nlohmann::json& metrics) {
  MetricsRead out;
  if (!metrics.is_object()) {
    out.errors.push_back({"", "must be an object"});
    return out;
  }
  for (const auto& [name, value] : metrics.items()) {
    auto check = checks().find(name);
    if (check == checks().end()) {
      out.dropped.push_back(name);
      continue;
    }
    if (auto why = check->second(value); !why.empty())
      out.errors.push_back({child_pointer("", name), why});
    else
      out.metrics[name] = value;
  }
  return out;
}

} // namespace slipfront::api
