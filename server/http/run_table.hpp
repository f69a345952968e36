// The run table of GET /api/v1/jobs?format=csv|ndjson: one flat row per job with its job
// columns, every spec field (`spec.friction.L`), every scalar metric (`metrics.outcome`,
// `metrics.rupture_speed.max`), the cost and the convergence status within its study.
#pragma once

#include "server/core/job.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::server {

// One flat row; keys keep the order: job columns, spec.*, metrics.* (arrays left out).
nlohmann::ordered_json run_row(const Job& job, const std::string& convergence_status);

// RFC 4180 CSV: a header (the union of the rows' keys, in first-seen order) and one line per
// row; empty cells for null or missing values; CRLF line ends.
std::string runs_csv(const std::vector<nlohmann::ordered_json>& rows);

// One JSON object per line.
std::string runs_ndjson(const std::vector<nlohmann::ordered_json>& rows);

} // namespace slipfront::server
