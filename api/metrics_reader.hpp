// Metrics JSON this code did not write (an imported run's), read back as metrics_json() writes
// it (docs/metrics.md "Metric names"): the names it writes, each with the kind of value it
// holds there. Unknown names are left out, so that no archive adds columns to every run table
// or keys to every listing.
#pragma once

#include "api/job_spec.hpp" // FieldError

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::api {

// The top-level names metrics_json() writes (and two older spellings of the rupture speed
// that api/metrics_row.cpp still reads).
const std::vector<std::string>& metric_names();

struct MetricsRead {
  nlohmann::json metrics = nlohmann::json::object(); // the known names, as given
  std::vector<FieldError> errors;   // a known name with a value it never holds ("/steps")
  std::vector<std::string> dropped; // the unknown names
};

// `metrics` (an object) checked: numbers finite (null for undefined), `steps` a whole number
// from 0 to 2^53, texts at most 4096 bytes, lists at most 100000 entries, the objects
// (`rupture_speed`, `mesh`, each of `stations`) of numbers.
MetricsRead read_metrics(const nlohmann::json& metrics);

} // namespace slipfront::api
