// JSON has no NaN or infinity: an undefined number (NaN, e.g. a front that never arrived)
// is written as null. Every JSON answer of the service uses this one rule.
// A whole number is written as an integer ("n_d": 10, not 10.0; byte counts, mesh sizes):
// every JSON answer and printed document passes through whole_numbers_as_integers.
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>

namespace slipfront::api {

inline nlohmann::json json_number(double value) {
  return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

// A byte count (an estimate may have a fraction) as a whole number of bytes.
inline nlohmann::json json_bytes(double bytes) {
  return std::isfinite(bytes) ? nlohmann::json(std::llround(bytes)) : nlohmann::json(nullptr);
}

// Rewrites, in place, every float of `j` that holds a whole number of magnitude at most 2^53
// (where every integer is exact in a double) as an integer of the same value; the others are
// kept. JSON has one number type: readers see the same values, people read "10", not "10.0".
template <class Json> void whole_numbers_as_integers(Json& j) {
  if (j.is_number_float()) {
    const double v = j.template get<double>();
    constexpr double exact_limit = 9007199254740992.0; // 2^53
    if (std::isfinite(v) && std::trunc(v) == v && std::fabs(v) <= exact_limit)
      j = static_cast<std::int64_t>(v);
    return;
  }
  if (j.is_structured())
    for (auto& element : j)
      whole_numbers_as_integers(element);
}

} // namespace slipfront::api
