// JSON has no NaN or infinity: an undefined number (NaN, e.g. a front that never arrived)
// is written as null. Every JSON answer of the service uses this one rule.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>

namespace slipfront::api {

inline nlohmann::json json_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

} // namespace slipfront::api
