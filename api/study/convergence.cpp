// Mesh convergence (docs/metrics.md "Convergence status"): the status of each run, the L × n_d
// convergence map and the refinement plan of a convergence request. The rules are spelled out in
// docs/studies.md.
#include "api/study/convergence.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "api/study/run_rules.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace slipfront::api {

using namespace study_rules;

namespace {

using nlohmann::json;

// docs/metrics.md "Convergence status": the partner of a run is the run of the same L at the next
// finer n_d present in the study; meshes whose runs all failed or were cancelled are skipped (no
// measurement).
const StudyRun* find_partner(const std::vector<StudyRun>& runs, const StudyRun& run) {
  std::vector<double> finer_meshes;
  for (const StudyRun& other : runs)
    if (same_value(other.L, run.L) && finer(other.n_d, run.n_d) &&
        state_of(other) != RunState::void_run)
      finer_meshes.push_back(other.n_d);
  if (finer_meshes.empty()) return nullptr;
  return pick_run(runs, run.L, unique_sorted(finer_meshes).front());
}

RunConvergence status_of(const std::vector<StudyRun>& runs, const StudyRun& run,
                         const ConvergenceTolerances& tol) {
  RunConvergence out;
  out.run_id = run.id;
  out.L = run.L;
  out.n_d = run.n_d;
  switch (state_of(run)) {
  case RunState::pending:
    out.status = ConvergenceStatus::pending;
    out.reason = std::string("job ") + to_string(run.status);
    return out;
  case RunState::void_run:
    out.status = ConvergenceStatus::failed;
    out.reason = std::string("job ") + to_string(run.status) + " without a result";
    return out;
  case RunState::diverged:
    out.status = ConvergenceStatus::diverged;
    out.reason = "the run diverged";
    return out;
  case RunState::measured:
    break;
  }
  const StudyRun* partner = find_partner(runs, run);
  if (!partner) {
    out.status = ConvergenceStatus::unknown;
    out.reason = "no finer mesh of this L in the study yet";
    return out;
  }
  out.partner_id = partner->id;
  out.partner_n_d = partner->n_d;
  const std::string against = "against n_d = " + number_text(partner->n_d) + ": ";
  if (state_of(*partner) == RunState::pending) {
    out.status = ConvergenceStatus::unknown;
    out.reason = against + "job " + to_string(partner->status);
    return out;
  }
  const Comparison c = compare(run, *partner, tol);
  out.status = c.agree ? ConvergenceStatus::converged : ConvergenceStatus::not_converged;
  out.propagation_distance_change = c.distance_change;
  out.arrival_time_change = c.arrival_change;
  out.reason = against + c.reason;
  return out;
}

// The cell of the map at (L, n_d): the run `pick` stands for it (pick_run), `s` is its status.
json cell_json(const std::vector<StudyRun>& runs, const StudyRun* pick, const RunConvergence& s,
               double L, double n_d) {
  json ids = json::array();
  for (const StudyRun& run : runs)
    if (same_value(run.L, L) && same_value(run.n_d, n_d)) ids.push_back(run.id);
  return {{"L", L},
          {"n_d", n_d},
          {"run_id", pick->id},
          {"run_ids", ids},
          {"status", to_string(s.status)},
          {"partner_n_d", json_number(s.partner_n_d)},
          {"changes", changes_json(s.propagation_distance_change, s.arrival_time_change)},
          {"reason", s.reason}};
}

} // namespace

std::string to_string(ConvergenceStatus status) {
  switch (status) {
  case ConvergenceStatus::converged:
    return "converged";
  case ConvergenceStatus::not_converged:
    return "not_converged";
  case ConvergenceStatus::unknown:
    return "unknown";
  case ConvergenceStatus::diverged:
    return "diverged";
  case ConvergenceStatus::pending:
    return "pending";
  case ConvergenceStatus::failed:
    return "failed";
  }
  return "unknown";
}

// docs/metrics.md "Convergence status"; docs/studies.md "Mesh-convergence status of a run".
std::vector<RunConvergence> convergence_statuses(const std::vector<StudyRun>& runs,
                                                 const ConvergenceTolerances& tol) {
  std::vector<RunConvergence> statuses;
  statuses.reserve(runs.size());
  for (const StudyRun& run : runs)
    statuses.push_back(status_of(runs, run, tol));
  return statuses;
}

// Paper Fig. 3c: the L × n_d convergence map.
nlohmann::json convergence_map(const std::vector<StudyRun>& runs,
                               const ConvergenceTolerances& tol) {
  const auto statuses = convergence_statuses(runs, tol);
  const auto Ls = study_values(runs, &StudyRun::L);
  const auto meshes = study_values(runs, &StudyRun::n_d);
  json cells = json::array();
  json converged_n_d = json::object();
  for (double L : Ls) {
    json smallest = nullptr; // the coarsest mesh whose cell is converged
    for (double n_d : meshes) {
      const StudyRun* pick = pick_run(runs, L, n_d);
      if (!pick) continue;
      const RunConvergence& s = statuses[static_cast<std::size_t>(pick - runs.data())];
      if (smallest.is_null() && s.status == ConvergenceStatus::converged) smallest = n_d;
      cells.push_back(cell_json(runs, pick, s, L, n_d));
    }
    converged_n_d[json(L).dump()] = smallest;
  }
  return {{"L", Ls}, {"n_d", meshes}, {"cells", cells}, {"converged_n_d", converged_n_d}};
}

std::string to_string(RefinementPlan::State state) {
  switch (state) {
  case RefinementPlan::State::run_next:
    return "run_next";
  case RefinementPlan::State::waiting:
    return "waiting";
  case RefinementPlan::State::converged:
    return "converged";
  case RefinementPlan::State::not_converged_at_cap:
    return "not_converged_at_cap";
  }
  return "run_next";
}

// The convergence criterion applied along a mesh ladder: refine until two successive meshes agree.
RefinementPlan refinement_plan(double L, const std::vector<StudyRun>& runs,
                               const std::vector<double>& ladder, double cap,
                               const ConvergenceTolerances& tol) {
  std::vector<StudyRun> of_L;
  std::copy_if(runs.begin(), runs.end(), std::back_inserter(of_L),
               [L](const StudyRun& run) { return same_value(run.L, L); });
  RefinementPlan plan;
  double finest_tried = not_available;
  const auto statuses = convergence_statuses(of_L, tol);
  for (std::size_t i = 0; i < of_L.size(); ++i) {
    const RunConvergence& s = statuses[i];
    if (s.status == ConvergenceStatus::converged && !(s.n_d >= plan.converged_n_d))
      plan.converged_n_d = s.n_d;
    if (s.status == ConvergenceStatus::pending) {
      plan.state = RefinementPlan::State::waiting;
      plan.reason =
          "n_d = " + number_text(s.n_d) + " is " + to_string(of_L[i].status) + "; wait for it";
    } else if (!(s.n_d <= finest_tried)) {
      finest_tried = s.n_d; // failed and cancelled runs count as tried: no endless retries
    }
  }
  if (std::isfinite(plan.converged_n_d)) {
    plan.state = RefinementPlan::State::converged;
    plan.reason = "mesh-converged at n_d = " + number_text(plan.converged_n_d);
    return plan;
  }
  if (plan.state == RefinementPlan::State::waiting) return plan;
  for (double n_d : unique_sorted(ladder)) {
    if (std::isfinite(finest_tried) && !finer(n_d, finest_tried)) continue;
    if (finer(n_d, cap)) break;
    plan.next_n_d = n_d;
    plan.reason =
        std::isfinite(finest_tried)
            ? "no two successive meshes up to n_d = " + number_text(finest_tried) + " agree"
            : "no run of this L yet";
    return plan;
  }
  plan.state = RefinementPlan::State::not_converged_at_cap;
  plan.reason = std::isfinite(finest_tried)
                    ? "not converged at cap: no two successive meshes up to n_d = " +
                          number_text(finest_tried) +
                          " agree and the ladder has no finer n_d <= " + number_text(cap)
                    : "not converged at cap: the ladder has no n_d <= " + number_text(cap);
  return plan;
}

} // namespace slipfront::api
