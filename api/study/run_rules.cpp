// The rules every study analysis shares (docs/studies.md): what a run contributes, which
// run stands for a cell, how two runs compare under the convergence criterion
// (docs/metrics.md "Convergence status").
#include "api/study/run_rules.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slipfront::api::study_rules {

using nlohmann::json;

// L and n_d come from JSON numbers: equal up to round-off means the same value.
bool same_value(double a, double b) {
  return std::abs(a - b) <= 1e-9 * std::max(std::abs(a), std::abs(b));
}

bool finer(double n_d, double than) {
  return n_d > than && !same_value(n_d, than);
}

std::vector<double> unique_sorted(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  std::vector<double> unique;
  for (double value : values)
    if (unique.empty() || !same_value(unique.back(), value)) unique.push_back(value);
  return unique;
}

std::string percent(double fraction) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g %%", 100.0 * fraction);
  return buffer;
}

std::string outcome_of(const StudyRun& run) {
  if (!run.metrics || !run.metrics->is_object()) return "";
  const auto it = run.metrics->find("outcome");
  return it != run.metrics->end() && it->is_string() ? it->get<std::string>() : "";
}

// A metric (docs/metrics.md); NaN when absent or null (e.g. arrival_time_at_probe never reached).
double metric(const StudyRun& run, const char* key) {
  if (!run.metrics || !run.metrics->is_object()) return not_available;
  const auto it = run.metrics->find(key);
  return it != run.metrics->end() && it->is_number() ? it->get<double>() : not_available;
}

// A run whose metrics say it took no step or simulated no time: whatever its status and
// outcome, it measured nothing (a run of 0 steps once ended "succeeded" with outcome
// no_rupture, and a study took it for a converged result).
bool simulated_nothing(const StudyRun& run) {
  const double steps = metric(run, "steps"), time = metric(run, "simulated_time");
  return (!std::isnan(steps) && steps <= 0.0) || (!std::isnan(time) && time <= 0.0);
}

RunState state_of(const StudyRun& run) {
  if (run.status == JobStatus::queued || run.status == JobStatus::running) return RunState::pending;
  if (run.status == JobStatus::cancelled || simulated_nothing(run)) return RunState::void_run;
  const std::string outcome = outcome_of(run);
  if (outcome == "diverged") return RunState::diverged;
  if (run.status == JobStatus::succeeded && !outcome.empty()) return RunState::measured;
  return RunState::void_run;
}

bool has_result(RunState state) {
  return state == RunState::measured || state == RunState::diverged;
}

// The run that stands for an (L, n_d) cell: a result before a pending run before a void
// one; among equals the smallest id (deterministic for duplicate submissions).
const StudyRun* pick_run(const std::vector<StudyRun>& runs, double L, double n_d) {
  const StudyRun* pick = nullptr;
  for (const StudyRun& run : runs) {
    if (!same_value(run.L, L) || !same_value(run.n_d, n_d)) continue;
    const auto rank = static_cast<int>(state_of(run));
    if (!pick || rank < static_cast<int>(state_of(*pick)) ||
        (rank == static_cast<int>(state_of(*pick)) && run.id < pick->id))
      pick = &run;
  }
  return pick;
}

// |value - reference| / |reference|; NaN if either is undefined.
double relative_change(double value, double reference) {
  if (!std::isfinite(value) || !std::isfinite(reference)) return not_available;
  if (reference == 0.0) return value == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return std::abs(value - reference) / std::abs(reference);
}

namespace {

std::string criterion_text(double change, double tolerance) {
  return percent(change) + (change < tolerance ? " (< " : " (not < ") + percent(tolerance) + ")";
}

} // namespace

// The station both fronts reached that the reference's front reached last (docs/metrics.md
// "Convergence status": the arrival time is compared where both ruptures arrive). None when
// either run has no stations in its metrics or no station was reached by both.
std::optional<StationArrival> common_station(const StudyRun& run, const StudyRun& reference) {
  const auto stations_of = [](const StudyRun& r) -> const json* {
    if (!r.metrics || !r.metrics->is_object()) return nullptr;
    const auto it = r.metrics->find("stations");
    return it != r.metrics->end() && it->is_array() ? &*it : nullptr;
  };
  const json* mine = stations_of(run);
  const json* theirs = stations_of(reference);
  if (!mine || !theirs) return std::nullopt;
  const auto time_of = [](const json& station) {
    const auto t = station.find("rupture_time");
    return t != station.end() && t->is_number() ? t->get<double>() : not_available;
  };
  std::optional<StationArrival> best;
  for (const json& ref_station : *theirs) {
    const double ref_time = time_of(ref_station);
    if (!std::isfinite(ref_time) || !ref_station.value("x1", json()).is_number()) continue;
    const double x1 = ref_station["x1"].get<double>();
    for (const json& station : *mine) {
      if (!station.value("x1", json()).is_number() || !same_value(station["x1"].get<double>(), x1))
        continue;
      const double time = time_of(station);
      if (std::isfinite(time) && (!best || ref_time > best->reference_time))
        best = StationArrival{x1, time, ref_time};
    }
  }
  return best;
}

// The convergence criterion (docs/metrics.md "Convergence status") between a run and its
// reference (the finer mesh, or the smaller L):
// same outcome; no_rupture in both agrees; otherwise propagation_distance within
// tol.propagation_distance and the front's arrival time within tol.arrival_time: at the probe
// (arrival_time_at_probe) when the front reached it in both runs; else, when the runs have
// stations, at the station both fronts reached last; else, if neither front reached the
// probe, distance alone (and if one did, they disagree).
Comparison compare(const StudyRun& run, const StudyRun& reference,
                   const ConvergenceTolerances& tol) {
  Comparison c;
  c.distance_change = relative_change(metric(run, distance_key), metric(reference, distance_key));
  c.arrival_change = relative_change(metric(run, arrival_key), metric(reference, arrival_key));
  const std::string mine = outcome_of(run);
  const std::string theirs = outcome_of(reference);
  if (theirs == "diverged") {
    c.reason = "it diverged";
    return c;
  }
  if (mine != theirs) {
    c.reason = "outcome " + mine + " vs " + theirs;
    return c;
  }
  if (mine == "no_rupture") {
    c.agree = true;
    c.reason = "no rupture in either run";
    return c;
  }
  if (std::isnan(c.distance_change)) {
    c.reason = "propagation_distance missing";
    return c;
  }
  const bool arrived = std::isfinite(metric(run, arrival_key));
  const bool reference_arrived = std::isfinite(metric(reference, arrival_key));
  const bool distance_ok = c.distance_change < tol.propagation_distance;
  const std::string distance_text = "propagation_distance changed by " +
                                    criterion_text(c.distance_change, tol.propagation_distance);
  if (arrived && reference_arrived) {
    c.agree = distance_ok && c.arrival_change < tol.arrival_time;
    c.reason = distance_text + ", arrival_time_at_probe by " +
               criterion_text(c.arrival_change, tol.arrival_time);
    return c;
  }
  if (const auto station = common_station(run, reference)) {
    c.arrival_change = relative_change(station->time, station->reference_time);
    c.agree = distance_ok && c.arrival_change < tol.arrival_time;
    c.reason = distance_text +
               ", the arrival time at the station x1 = " + number_text(station->x1) +
               " (the farthest both fronts reached; the probe " +
               (arrived || reference_arrived ? "in one run only" : "in neither") + ") by " +
               criterion_text(c.arrival_change, tol.arrival_time);
    return c;
  }
  if (arrived != reference_arrived) {
    c.reason = "the front reached the probe in one run only";
    return c;
  }
  c.agree = distance_ok;
  c.reason =
      distance_text + "; the front reached the probe in neither run (judged on distance alone)";
  return c;
}

std::vector<double> study_values(const std::vector<StudyRun>& runs, double StudyRun::*field) {
  std::vector<double> values;
  for (const StudyRun& run : runs)
    values.push_back(run.*field);
  return unique_sorted(values);
}

namespace {

bool has_converged_run(const std::vector<RunConvergence>& statuses, double L) {
  return std::any_of(statuses.begin(), statuses.end(), [L](const RunConvergence& s) {
    return same_value(s.L, L) && s.status == ConvergenceStatus::converged;
  });
}

} // namespace

// The reference run of an L (docs/studies.md): its finest run with a non-diverged result,
// provided the L has at least one mesh-converged run; otherwise none.
const StudyRun* reference_run(const std::vector<StudyRun>& runs,
                              const std::vector<RunConvergence>& statuses, double L) {
  if (!has_converged_run(statuses, L)) return nullptr;
  const StudyRun* finest = nullptr;
  for (const StudyRun& run : runs) {
    if (!same_value(run.L, L) || state_of(run) != RunState::measured) continue;
    if (!finest || finer(run.n_d, finest->n_d) ||
        (same_value(run.n_d, finest->n_d) && run.id < finest->id))
      finest = &run;
  }
  return finest;
}

json changes_json(double distance_change, double arrival_change) {
  return {{distance_key, json_number(distance_change)},
          {"arrival_time", json_number(arrival_change)}};
}

} // namespace slipfront::api::study_rules
