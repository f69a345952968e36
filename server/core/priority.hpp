// A job's priority: higher runs first, FIFO within a priority (server/run/job_queue.hpp). Its
// one range, for the job body and the ?priority= of POST /api/v1/jobs, the study body and
// the OpenAPI document.
#pragma once

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace slipfront::server {

constexpr int lowest_priority = -100;
constexpr int highest_priority = 100;

// What a bad priority is told: "must be an integer in [-100, 100]".
std::string priority_rule();

// The priority `value` gives, if it is an integer in the range.
std::optional<int> priority_of(long value);
std::optional<int> priority_of(const nlohmann::json& value);

} // namespace slipfront::server
