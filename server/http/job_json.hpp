// A job as the API shows it (GET /api/v1/jobs/{id} and every answer that carries a job).
#pragma once

#include "server/core/job.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::server {

// The job as the API shows it. `fields` (if not empty) keeps only these top-level keys
// (and always "id").
nlohmann::json job_to_json(const Job& job, const std::vector<std::string>& fields = {});

} // namespace slipfront::server
