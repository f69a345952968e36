// Answers at a stated accuracy (docs/studies-api.md "Accuracy target"): the error estimate of
// a mesh ladder and when to stop refining.
#include "api/study/accuracy_target.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "api/study/run_rules.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::api {

using nlohmann::json;
using namespace study_rules;

const std::vector<std::string>& accuracy_metrics() {
  static const std::vector<std::string> names = {"arrest_position",       "propagation_distance",
                                                 "arrival_time_at_probe", "max_slip_velocity",
                                                 "rupture_speed.max",     "rupture_speed.mean"};
  return names;
}

bool is_node_quantised(const std::string& metric) {
  return metric == "arrest_position" || metric == "propagation_distance";
}

double accuracy_metric(const StudyRun& run, const std::string& metric) {
  if (!run.metrics || !run.metrics->is_object()) return not_available;
  const json* node = &*run.metrics;
  std::size_t start = 0;
  while (start <= metric.size()) {
    const std::size_t dot = std::min(metric.find('.', start), metric.size());
    const auto it = node->find(metric.substr(start, dot - start));
    if (it == node->end()) return not_available;
    node = &*it;
    start = dot + 1;
    if (dot == metric.size()) break;
    if (!node->is_object()) return not_available;
  }
  return node->is_number() ? node->get<double>() : not_available;
}

std::string to_string(AccuracyVerdict::State state) {
  switch (state) {
  case AccuracyVerdict::State::waiting:
    return "waiting";
  case AccuracyVerdict::State::run_next:
    return "run_next";
  case AccuracyVerdict::State::met:
    return "met";
  case AccuracyVerdict::State::mesh_cap:
    return "mesh_cap";
  case AccuracyVerdict::State::failed:
    return "failed";
  }
  return "waiting";
}

namespace {

// One mesh of the ladder with its value (NaN until measured).
struct Rung {
  double n_d;
  double value;
};

struct Estimate {
  double error = not_available;
  std::string how;
  double order = not_available;
  double extrapolated = not_available;
};

// The error estimate of rungs[k] (k >= 1) from it and the meshes below it (see the header).
Estimate estimate_at(const std::vector<Rung>& rungs, std::size_t k, bool quantised) {
  Estimate e;
  const double a = rungs[k - 1].value, b = rungs[k].value;
  const double ratio = rungs[k].n_d / rungs[k - 1].n_d;
  const double change = std::abs(b - a);
  e.error = change;
  e.how = "last refinement";
  if (k >= 2) {
    const double earlier = std::abs(a - rungs[k - 2].value);
    const double earlier_ratio = rungs[k - 1].n_d / rungs[k - 2].n_d;
    if (change > 0.0 && earlier > change && std::abs(earlier_ratio - ratio) < 1e-9 * ratio) {
      // Richardson (e.g. Roache 1998, "Verification and Validation in Computational Science"):
      // e_fine = |b - a| / (r^p - 1), p = ln(earlier / change) / ln r.
      e.order = std::clamp(std::log(earlier / change) / std::log(ratio), 0.5, 4.0);
      const double denominator = std::pow(ratio, e.order) - 1.0;
      e.error = change / denominator;
      e.extrapolated = b + (b - a) / denominator;
      e.how = "Richardson";
    }
  }
  if (quantised && e.error < 1.0 / rungs[k].n_d) {
    e.error = 1.0 / rungs[k].n_d;
    e.how = "node spacing";
  }
  return e;
}

double relative(double error, double value) {
  return value != 0.0 ? error / std::abs(value) : not_available;
}

bool meets(double error, double value, double tolerance) {
  const double r = relative(error, value);
  return !std::isnan(r) && r <= tolerance;
}

std::string mesh_text(double n_d) {
  return "n_d = " + number_text(n_d);
}

// The ladder from `first` up to the cap, each with the value of its run when measured.
std::vector<Rung> rungs_of(const AccuracyTarget& target, const std::vector<double>& ladder,
                           std::size_t first, double n_d_max, const std::vector<StudyRun>& runs) {
  std::vector<Rung> rungs;
  for (std::size_t i = first; i < ladder.size(); ++i) {
    if (ladder[i] > n_d_max && !same_value(ladder[i], n_d_max)) break;
    const StudyRun* run = pick_run(runs, target.L, ladder[i]);
    const bool measured = run && state_of(*run) == RunState::measured;
    rungs.push_back({ladder[i], measured ? accuracy_metric(*run, target.metric) : not_available});
  }
  return rungs;
}

} // namespace

AccuracyVerdict accuracy_verdict(const AccuracyTarget& target, const std::vector<double>& ladder,
                                 std::size_t first, double n_d_max,
                                 const std::vector<StudyRun>& runs) {
  AccuracyVerdict v;
  const bool quantised = is_node_quantised(target.metric);
  std::vector<Rung> rungs = rungs_of(target, ladder, first, n_d_max, runs);
  const std::string wanted = target.metric + " within " + percent(target.tolerance);
  for (std::size_t k = 0; k < rungs.size(); ++k) {
    const StudyRun* run = pick_run(runs, target.L, rungs[k].n_d);
    if (!run) {
      v.state = AccuracyVerdict::State::run_next;
      v.next_n_d = rungs[k].n_d;
      v.reason = k == 0 ? "the ladder starts at " + mesh_text(rungs[k].n_d)
                        : v.reason + "; next: " + mesh_text(rungs[k].n_d);
      return v;
    }
    const RunState state = state_of(*run);
    if (state == RunState::pending) {
      v.state = AccuracyVerdict::State::waiting;
      v.reason = "waiting for " + mesh_text(rungs[k].n_d) + " (job " + run->id + ")";
      return v;
    }
    if (state != RunState::measured || std::isnan(rungs[k].value)) {
      v.state = AccuracyVerdict::State::failed;
      const std::string outcome = outcome_of(*run);
      v.reason = "the run at " + mesh_text(rungs[k].n_d) + " (job " + run->id + ", " +
                 (state == RunState::diverged   ? std::string("diverged")
                  : state == RunState::void_run ? std::string("no result")
                                                : "outcome " + outcome) +
                 ") has no " + target.metric + ": the target cannot be met on this scene";
      return v;
    }
    json step = {{"n_d", rungs[k].n_d},
                 {"job_id", run->id},
                 {"value", rungs[k].value},
                 {"wall_time_s", run->wall_time_s}};
    v.value = rungs[k].value;
    v.n_d = rungs[k].n_d;
    if (k == 0) {
      v.steps.push_back(step);
      v.reason = mesh_text(rungs[k].n_d) + " gives " + number_text(v.value) +
                 " (no estimate from one mesh)";
      continue;
    }
    const Estimate e = estimate_at(rungs, k, quantised);
    v.error = e.error;
    v.relative_error = relative(e.error, v.value);
    v.estimate = e.how;
    v.observed_order = e.order;
    v.extrapolated = e.extrapolated;
    step["change"] = std::abs(rungs[k].value - rungs[k - 1].value);
    step["error"] = e.error;
    step["relative_error"] = json_number(v.relative_error);
    step["estimate"] = e.how;
    v.steps.push_back(step);
    const std::string said = mesh_text(rungs[k].n_d) + " gives " + number_text(v.value) + " ± " +
                             number_text(e.error) + " (" + percent(v.relative_error) + ", " +
                             e.how + ")";
    if (meets(e.error, v.value, target.tolerance)) {
      v.state = AccuracyVerdict::State::met;
      v.reason = said + ": meets " + wanted;
      return v;
    }
    v.reason = said + ": not yet " + wanted;
  }
  v.state = AccuracyVerdict::State::mesh_cap;
  v.reason += rungs.empty() ? "no mesh of the ladder is at or below n_d_max"
                            : "; the ladder ends at " + mesh_text(rungs.back().n_d) +
                                  " (n_d_max): raise n_d_max or accept the estimate";
  return v;
}

std::size_t accuracy_start(const AccuracyTarget& target, const std::vector<double>& ladder,
                           double n_d_max, const std::vector<StudyRun>& scene_runs,
                           std::string& why) {
  const std::vector<Rung> rungs = rungs_of(target, ladder, 0, n_d_max, scene_runs);
  const bool quantised = is_node_quantised(target.metric);
  std::size_t start = 0;
  for (std::size_t k = 1; k + 1 < rungs.size(); ++k) {
    if (std::isnan(rungs[k - 1].value) || std::isnan(rungs[k].value)) continue;
    // An unmeasured mesh below k is NaN: estimate_at then falls back to the last refinement.
    const Estimate e = estimate_at(rungs, k, quantised);
    if (meets(e.error, rungs[k].value, target.tolerance)) break;
    start = k;
    why = "the database has " + mesh_text(rungs[k - 1].n_d) + " and " + mesh_text(rungs[k].n_d) +
          " of this scene and L: " + percent(relative(e.error, rungs[k].value)) + " > " +
          percent(target.tolerance) + ", so the ladder starts at " + mesh_text(rungs[k].n_d);
  }
  if (start == 0)
    why = "no pair of meshes of this scene and L in the database settles it: the ladder starts "
          "at its first mesh, " +
          (rungs.empty() ? std::string("none") : mesh_text(rungs.front().n_d));
  return start;
}

json to_json(const AccuracyVerdict& v) {
  return {{"state", to_string(v.state)},
          {"reason", v.reason},
          {"value", json_number(v.value)},
          {"error", json_number(v.error)},
          {"relative_error", json_number(v.relative_error)},
          {"n_d", json_number(v.n_d)},
          {"estimate", v.estimate.empty() ? json(nullptr) : json(v.estimate)},
          {"observed_order", json_number(v.observed_order)},
          {"extrapolated", json_number(v.extrapolated)},
          {"next_n_d", json_number(v.next_n_d)},
          {"steps", v.steps}};
}

} // namespace slipfront::api
