// The metrics and the front profile as JSON (docs/metrics.md "Metric names": the names are
// part of the API).
#include "api/json_number.hpp"
#include "api/run_job.hpp"
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/friction/strength_update.hpp"
#include "solver/methods.hpp"
#include "solver/run/station_summary.hpp"

#include <cmath>

namespace slipfront::api {

namespace {

nlohmann::json numbers(const std::vector<double>& values) {
  nlohmann::json array = nlohmann::json::array();
  for (double value : values)
    array.push_back(json_number(value));
  return array;
}

// Each station's rupture time (null where it never ruptured), peak slip rate and its time, and
// final slip (docs/metrics.md "Other metrics").
nlohmann::json stations_json(const StationRecords& stations) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t s = 0; s < stations.x1.size(); ++s) {
    const StationSummary summary = summarize_station(stations, s, stations.rupture_threshold);
    list.push_back({{"x1", json_number(stations.x1[s])},
                    {"rupture_time", json_number(stations.rupture_time[s])},
                    {"peak_slip_rate", json_number(summary.peak_slip_rate)},
                    {"peak_time", json_number(summary.peak_time)},
                    {"final_slip", json_number(summary.final_slip)}});
  }
  return list;
}

} // namespace

std::string method_description(const SimulationParams& params) {
  // The discretisation and its options are the method's (its entry's describe).
  std::string method = method_entry(params.method).describe(params);
  const RegularizationLaw& regularization = effective_regularization(params.friction);
  method += "; friction: " + params.friction.law;
  if (!regularization.filters()) return method;
  if (!*coefficient_law(params.friction).fixed_regularization()) // else implied by the law
    method += std::string(", ") + regularization.description().name + " regularization";
  return method + ", " + to_string(params.friction.update) + " strength update";
}

nlohmann::json metrics_json(const RunResult& result) {
  const Metrics& m = result.metrics;
  nlohmann::json j;
  j["front_threshold"] = json_number(m.front_threshold);
  j["arrest_position"] = json_number(m.arrest_position);
  j["propagation_distance"] = json_number(m.propagation_distance);
  j["arrival_time_at_probe"] = json_number(m.arrival_time_at_probe);
  j["probe_x1"] = json_number(m.probe_x1);
  j["rupture_speed"] = {{"max", json_number(m.max_rupture_speed)},
                        {"mean", json_number(m.mean_rupture_speed)}};
  j["max_slip_velocity"] = json_number(m.max_slip_velocity);
  j["outcome"] = to_string(m.outcome);
  j["energy_error"] = json_number(m.energy_error);
  j["wall_time_s"] = json_number(m.wall_time_s);
  j["steps"] = m.steps;
  j["dt"] = json_number(m.dt);
  j["stable_dt"] = json_number(result.mesh.stable_dt);
  j["simulated_time"] = json_number(m.simulated_time);
  j["spectral_critical_length"] = json_number(m.spectral_critical_length);
  j["spectral_frequency"] = json_number(m.spectral_frequency);
  j["spectral_velocity"] = json_number(m.spectral_velocity);
  j["warnings"] = m.warnings;
  j["message"] = m.message;
  j["cancelled"] = result.cancelled;
  j["mesh"] = {{"nx", result.mesh.nx},
               {"ny", result.mesh.ny},
               {"dx", json_number(result.mesh.dx)},
               {"height", json_number(result.mesh.height)},
               {"threads", result.mesh.threads}};
  if (result.mesh.lower_ny > 0) { // FE with an elastic lower solid: its block
    j["mesh"]["lower_ny"] = result.mesh.lower_ny;
    j["mesh"]["lower_height"] = json_number(result.mesh.lower_height);
  }
  if (!result.stations.empty()) j["stations"] = stations_json(result.stations);
  j["code_version"] = code_version();
  const MethodEntry& method = method_entry(result.mesh.method);
  j["method"] = std::string(method.method.name());
  j["method_description"] = method.discretisation;
  return j;
}

nlohmann::json metrics_json(const RunResult& result, const SimulationParams& params) {
  nlohmann::json j = metrics_json(result);
  j["method"] = std::string(params.method.name());
  j["method_description"] = method_description(params);
  return j;
}

nlohmann::json front_json(const RunResult& result) {
  return {{"x1", numbers(result.front.x1)},
          {"arrival_time", numbers(result.front.arrival_time)},
          {"rupture_speed", numbers(result.front.rupture_speed)}};
}

} // namespace slipfront::api
