// Speed and accuracy of the runs of a study: cost against the errors relative to the
// reference run of each L, and the relative L2 error of a time record (docs/studies.md).
#include "api/study/speed_accuracy.hpp"

#include "api/json_number.hpp"
#include "api/study/run_rules.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slipfront::api {

using namespace study_rules;

namespace {

using nlohmann::json;

void check_samples(const std::vector<double>& t, const std::vector<double>& v, const char* name) {
  if (t.size() != v.size())
    throw std::invalid_argument(std::string(name) + ": times and values differ in length");
  for (std::size_t i = 1; i < t.size(); ++i)
    if (!(t[i] > t[i - 1]))
      throw std::invalid_argument(std::string(name) + ": times must increase");
}

double interpolate(const std::vector<double>& t, const std::vector<double>& v, double at) {
  const auto upper = std::upper_bound(t.begin(), t.end(), at);
  if (upper == t.begin()) return v.front();
  if (upper == t.end()) return v.back();
  const auto i = static_cast<std::size_t>(upper - t.begin());
  const double weight = (at - t[i - 1]) / (t[i] - t[i - 1]);
  return v[i - 1] + weight * (v[i] - v[i - 1]);
}

// Every result says how accurate it is and what it cost (docs/studies.md "Speed and accuracy").
// One speed-accuracy entry: the run's cost and its errors against `ref` (null: no reference).
json speed_accuracy_entry(const StudyRun& run, const StudyRun* ref) {
  const bool judged = ref && state_of(run) == RunState::measured;
  // No rupture in either run: the outcome agrees and there is no rupture to measure
  // (a nucleation patch's slip is not a propagation distance), as in compare().
  const bool neither_ruptured =
      judged && outcome_of(run) == "no_rupture" && outcome_of(*ref) == "no_rupture";
  const double arrival_error =
      judged ? relative_change(metric(run, arrival_key), metric(*ref, arrival_key)) : not_available;
  const double distance_error =
      neither_ruptured ? 0.0
      : judged         ? relative_change(metric(run, distance_key), metric(*ref, distance_key))
                       : not_available;
  return {{"id", run.id},
          {"L", run.L},
          {"n_d", run.n_d},
          {"outcome", outcome_of(run)},
          {"wall_time_s", json_number(run.wall_time_s)},
          {"memory_bytes", json_number(run.memory_bytes)},
          {"reference_run_id", ref ? json(ref->id) : json(nullptr)},
          {"errors", changes_json(distance_error, arrival_error)}};
}

} // namespace

nlohmann::json speed_accuracy(const std::vector<StudyRun>& runs, const ConvergenceTolerances& tol) {
  const auto statuses = convergence_statuses(runs, tol);
  json list = json::array();
  for (const StudyRun& run : runs)
    if (has_result(state_of(run)))
      list.push_back(speed_accuracy_entry(run, reference_run(runs, statuses, run.L)));
  return list;
}

nlohmann::json speed_accuracy_across_methods(const MethodRuns& first, const MethodRuns& second,
                                             const ConvergenceTolerances& tol) {
  const TwoMethods both(first, second, tol);
  // The reference of an L: the finer of the two methods' references (the second on a tie).
  auto reference_of = [&](double L) -> std::pair<const StudyRun*, const std::string*> {
    const StudyRun* a = both.first_reference(L);
    const StudyRun* b = both.second_reference(L);
    if (a && (!b || finer(a->n_d, b->n_d))) return {a, &first.method};
    return {b, b ? &second.method : nullptr};
  };
  json list = json::array();
  for (const MethodRuns* side : {&first, &second})
    for (const StudyRun& run : side->runs) {
      if (!has_result(state_of(run))) continue;
      const auto [ref, ref_method] = reference_of(run.L);
      json entry = speed_accuracy_entry(run, ref);
      entry["method"] = side->method;
      entry["reference_method"] = ref_method ? json(*ref_method) : json(nullptr);
      list.push_back(std::move(entry));
    }
  return list;
}

// Relative L2 error of a time record against a reference record (docs/studies.md).
double relative_l2_error(const std::vector<double>& t_a, const std::vector<double>& v_a,
                         const std::vector<double>& t_ref, const std::vector<double>& v_ref) {
  check_samples(t_a, v_a, "record");
  check_samples(t_ref, v_ref, "reference");
  if (t_a.empty() || t_ref.empty()) return not_available;
  const double begin = std::max(t_a.front(), t_ref.front());
  const double end = std::min(t_a.back(), t_ref.back());
  double error = 0.0, norm = 0.0, previous_t = 0.0, previous_e = 0.0, previous_r = 0.0;
  std::size_t used = 0;
  for (std::size_t i = 0; i < t_a.size(); ++i) {
    if (t_a[i] < begin || t_a[i] > end) continue;
    const double r = interpolate(t_ref, v_ref, t_a[i]);
    const double e = v_a[i] - r;
    if (used++ > 0) {
      const double dt = t_a[i] - previous_t;
      error += 0.5 * dt * (e * e + previous_e * previous_e);
      norm += 0.5 * dt * (r * r + previous_r * previous_r);
    }
    previous_t = t_a[i];
    previous_e = e;
    previous_r = r;
  }
  if (used < 2 || norm == 0.0) return not_available;
  return std::sqrt(error / norm);
}

const std::optional<ProbeSeries>& SlipVelocityErrors::record_of(const std::string& run_id) {
  const auto it = records_.find(run_id);
  if (it != records_.end()) return it->second;
  std::string why;
  std::optional<ProbeSeries> record = read_(run_id, why);
  why_[run_id] = why;
  return records_.emplace(run_id, std::move(record)).first->second;
}

void SlipVelocityErrors::add_to(nlohmann::json& entry) {
  const std::string run_id = entry["id"].get<std::string>();
  entry["job_id"] = run_id;
  json l2 = nullptr;
  std::string why;
  if (entry["reference_run_id"].is_string()) {
    const std::string ref_id = entry["reference_run_id"].get<std::string>();
    const auto& mine = record_of(run_id);
    const auto& ref = record_of(ref_id);
    if (mine && ref) {
      try {
        l2 = json_number(
            relative_l2_error(mine->time, mine->slip_velocity, ref->time, ref->slip_velocity));
        probe_x1_ = ref->x1;
        if (l2.is_null())
          why = "undefined: the reference record is zero over the common time range (no "
                "slip at the probe) or fewer than two samples overlap";
      } catch (const std::exception& e) {
        why = e.what();
      }
    } else {
      why = !mine ? why_[run_id] : "reference: " + why_[ref_id];
    }
  } else {
    why = "no reference run (this L has no mesh-converged run)";
  }
  entry["errors"]["slip_velocity_l2"] = l2;
  if (l2.is_null()) entry["slip_velocity_l2_unavailable"] = why;
}

nlohmann::json speed_accuracy_by_regime(const std::vector<RegimeRun>& runs,
                                        SlipVelocityErrors& errors) {
  std::map<std::string, std::vector<StudyRun>> groups;
  for (const RegimeRun& r : runs)
    groups[r.regime].push_back(r.run);
  json list = json::array();
  for (const auto& [regime, members] : groups)
    for (auto entry : speed_accuracy(members)) {
      if (!regime.empty()) entry["regime"] = regime;
      errors.add_to(entry);
      list.push_back(std::move(entry));
    }
  return list;
}

} // namespace slipfront::api
