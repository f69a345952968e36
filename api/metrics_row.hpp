// The metrics that the server's jobs database keeps as columns of its metrics table (so runs
// are searched and sorted without parsing JSON): one value per column, unset where the
// metric is undefined (NaN, e.g. a front that never arrived) and stored as NULL.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace slipfront::api {

struct MetricsRow {
  std::optional<double> arrest_position;
  std::optional<double> propagation_distance;
  std::optional<double> arrival_time_at_probe;
  std::optional<double> max_rupture_speed;
  std::optional<double> mean_rupture_speed;
  std::optional<double> max_slip_velocity;
  std::optional<std::string> outcome;
  std::optional<double> energy_error;
  std::optional<double> wall_time_s; // the solver's; unset: the caller's measured wall time
  std::optional<std::int64_t> steps;
  std::optional<double> dt;
  std::optional<double> simulated_time;
};

// From the metrics JSON (metrics_json(), api/run_job.hpp), whichever runner ran the job (a
// worker of the server, or `slipfront run` on a compute node, whose report file carries the
// JSON): the server's store derives the row here, once, when a run's record is stored.
// Missing or non-numeric entries are unset; the rupture speeds are read from "rupture_speed":
// {"max", "mean"} (or flat "max_rupture_speed", "mean_rupture_speed").
MetricsRow metrics_row(const nlohmann::json& metrics);

} // namespace slipfront::api
