#include "api/metrics_row.hpp"

#include <cmath>

namespace slipfront::api {

namespace {

std::optional<double> finite(double v) {
  return std::isfinite(v) ? std::optional<double>(v) : std::nullopt;
}

// metrics[key] (or metrics[key][nested]) if it is a finite number.
std::optional<double> number(const nlohmann::json& metrics, const char* key,
                             const char* nested = nullptr) {
  if (!metrics.is_object()) return std::nullopt;
  auto it = metrics.find(key);
  if (it == metrics.end()) return std::nullopt;
  if (nested) {
    if (!it->is_object()) return std::nullopt;
    auto inner = it->find(nested);
    if (inner == it->end() || !inner->is_number()) return std::nullopt;
    return inner->get<double>();
  }
  if (!it->is_number()) return std::nullopt;
  return finite(it->get<double>());
}

std::optional<double> either(std::optional<double> a, std::optional<double> b) {
  return a ? a : b;
}

} // namespace

MetricsRow metrics_row(const nlohmann::json& x) {
  MetricsRow row;
  row.arrest_position = number(x, "arrest_position");
  row.propagation_distance = number(x, "propagation_distance");
  row.arrival_time_at_probe = number(x, "arrival_time_at_probe");
  row.max_rupture_speed = either(number(x, "max_rupture_speed"), number(x, "rupture_speed", "max"));
  row.mean_rupture_speed =
      either(number(x, "mean_rupture_speed"), number(x, "rupture_speed", "mean"));
  row.max_slip_velocity = number(x, "max_slip_velocity");
  if (x.is_object() && x.contains("outcome") && x["outcome"].is_string())
    row.outcome = x["outcome"].get<std::string>();
  row.energy_error = number(x, "energy_error");
  row.wall_time_s = number(x, "wall_time_s");
  // A whole number that an int64 holds exactly (an imported record may say 1e300).
  if (auto steps = number(x, "steps");
      steps && *steps >= 0.0 && *steps <= 9007199254740992.0 && std::floor(*steps) == *steps)
    row.steps = static_cast<std::int64_t>(*steps);
  row.dt = number(x, "dt");
  row.simulated_time = number(x, "simulated_time");
  return row;
}

} // namespace slipfront::api
