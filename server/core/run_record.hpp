// The run record: what a finished run leaves behind, the one shape of a run's result
// between the runners (server/run/) and the store (server/db/job_store.hpp).
#pragma once

#include "api/metrics_row.hpp"
#include "server/core/job.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace slipfront::server {

struct RunRecord {
  JobStatus status = JobStatus::succeeded;
  std::string error;
  nlohmann::json metrics; // null if none
  nlohmann::json front;   // null if none
  ResultFile result;
  double wall_time_s = 0.0;
  std::string finished_at;
  // The columns of the metrics row. Unset (a run whose metrics arrived as JSON only): read
  // from `metrics` (api::metrics_row).
  std::optional<api::MetricsRow> metrics_row;
};

} // namespace slipfront::server
