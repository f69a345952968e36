// Study analysis of SPEC §2: convergence status, convergence map, critical length,
// speed/accuracy and refinement plans. The rules are spelled out in docs/studies.md.
#include "api/study_analysis.hpp"

#include "api/job_spec.hpp"
#include "api/json_number.hpp"
#include "api/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <stdexcept>

namespace slipfront::api {

namespace {

using nlohmann::json;

constexpr const char* distance_key = "propagation_distance";
constexpr const char* arrival_key = "arrival_time_at_probe";

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

// A metric of SPEC §2; NaN when absent or null (e.g. arrival_time_at_probe never reached).
double metric(const StudyRun& run, const char* key) {
  if (!run.metrics || !run.metrics->is_object()) return not_available;
  const auto it = run.metrics->find(key);
  return it != run.metrics->end() && it->is_number() ? it->get<double>() : not_available;
}

// What a run contributes. The server stores a diverged run as job status "failed" with
// metrics outcome "diverged" (server/job_runner.cpp): it is a result, not a void run.
enum class RunState { measured, diverged, pending, void_run };

RunState state_of(const StudyRun& run) {
  if (run.status == "queued" || run.status == "running") return RunState::pending;
  if (run.status == "cancelled") return RunState::void_run;
  const std::string outcome = outcome_of(run);
  if (outcome == "diverged") return RunState::diverged;
  if (run.status == "succeeded" && !outcome.empty()) return RunState::measured;
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

struct Comparison {
  bool agree = false;
  double distance_change = not_available;
  double arrival_change = not_available;
  std::string reason;
};

std::string criterion_text(double change, double tolerance) {
  return percent(change) + (change < tolerance ? " (< " : " (not < ") + percent(tolerance) + ")";
}

// SPEC §2 criterion between a run and its reference (the finer mesh, or the smaller L):
// same outcome; no_rupture in both agrees; otherwise propagation_distance within
// tol.propagation_distance and arrival_time_at_probe within tol.arrival_time, the latter
// judged only when the front reached the probe in both runs (in neither: distance alone).
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
  if (arrived != std::isfinite(metric(reference, arrival_key))) {
    c.reason = "the front reached the probe in one run only";
    return c;
  }
  const bool distance_ok = c.distance_change < tol.propagation_distance;
  const bool arrival_ok = !arrived || c.arrival_change < tol.arrival_time;
  c.agree = distance_ok && arrival_ok;
  c.reason =
      "propagation_distance changed by " +
      criterion_text(c.distance_change, tol.propagation_distance) +
      (arrived ? ", arrival_time_at_probe by " + criterion_text(c.arrival_change, tol.arrival_time)
               : "; the front reached the probe in neither run (judged on distance alone)");
  return c;
}

// SPEC §2: the partner of a run is the run of the same L at the next finer n_d present in
// the study; meshes whose runs all failed or were cancelled are skipped (no measurement).
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
    out.reason = "job " + run.status;
    return out;
  case RunState::void_run:
    out.status = ConvergenceStatus::failed;
    out.reason = "job " + run.status + " without a result";
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
    out.reason = against + "job " + partner->status;
    return out;
  }
  const Comparison c = compare(run, *partner, tol);
  out.status = c.agree ? ConvergenceStatus::converged : ConvergenceStatus::not_converged;
  out.propagation_distance_change = c.distance_change;
  out.arrival_time_change = c.arrival_change;
  out.reason = against + c.reason;
  return out;
}

std::vector<double> study_values(const std::vector<StudyRun>& runs, double StudyRun::*field) {
  std::vector<double> values;
  for (const StudyRun& run : runs)
    values.push_back(run.*field);
  return unique_sorted(values);
}

bool has_converged_run(const std::vector<RunConvergence>& statuses, double L) {
  return std::any_of(statuses.begin(), statuses.end(), [L](const RunConvergence& s) {
    return same_value(s.L, L) && s.status == ConvergenceStatus::converged;
  });
}

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

json cell_json(const std::vector<StudyRun>& runs, const std::vector<RunConvergence>& statuses,
               double L, double n_d) {
  const StudyRun* pick = pick_run(runs, L, n_d);
  if (!pick) return nullptr;
  const RunConvergence& s = statuses[static_cast<std::size_t>(pick - runs.data())];
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

json reference_json(double L, const StudyRun& run) {
  return {{"L", L},
          {"run_id", run.id},
          {"n_d", run.n_d},
          {"outcome", outcome_of(run)},
          {distance_key, json_number(metric(run, distance_key))},
          {arrival_key, json_number(metric(run, arrival_key))},
          {"spectral_critical_length", json_number(metric(run, "spectral_critical_length"))}};
}

struct Reference {
  double L;
  const StudyRun* run;
};

// SPEC §2 read as the paper does (§4: "every simulation with L <= L_c obeys the same
// behaviour"): the number of smallest references that all agree pairwise.
std::size_t agreeing_prefix(const std::vector<std::vector<bool>>& agree) {
  std::size_t prefix = agree.empty() ? 0 : 1;
  while (prefix < agree.size() && std::all_of(agree[prefix].begin(), agree[prefix].begin() + prefix,
                                              [](bool b) { return b; }))
    ++prefix;
  return prefix;
}

// How much the metrics change from each mesh-converged L to the next larger one: what a
// reader needs when no L meets the rule (docs/studies.md).
json steps_in_L(const std::vector<Reference>& refs, const ConvergenceTolerances& tol) {
  json steps = json::array();
  for (std::size_t k = 1; k < refs.size(); ++k) {
    const Comparison c = compare(*refs[k].run, *refs[k - 1].run, tol);
    steps.push_back({{"from_L", refs[k - 1].L},
                     {"to_L", refs[k].L},
                     {"changes", changes_json(c.distance_change, c.arrival_change)},
                     {"agree", c.agree}});
  }
  return steps;
}

// "1e-06 -> 5e-06: 2.8 % / n/a; ..." for the reason text.
std::string describe_steps(const json& steps) {
  std::string out;
  for (const json& step : steps) {
    const auto change = [&](const char* key) {
      const json& v = step["changes"][key];
      return v.is_number() ? percent(v.get<double>()) : std::string("n/a");
    };
    out += (out.empty() ? "" : "; ") + number_text(step["from_L"].get<double>()) + " -> " +
           number_text(step["to_L"].get<double>()) + ": " + change(distance_key) + " / " +
           change("arrival_time");
  }
  return out;
}

void explain_critical_length(json& result, const std::vector<Reference>& refs, std::size_t prefix) {
  result["L_c"] = nullptr;
  result["next_larger_L"] = nullptr;
  if (refs.size() < 2) {
    result["reason"] = "needs at least two mesh-converged L, the study has " +
                       std::to_string(refs.size()) + ": add L values or refine meshes";
    return;
  }
  if (prefix < 2) {
    result["next_larger_L"] = refs[1].L;
    const bool none_agree = std::none_of(result["steps_in_L"].begin(), result["steps_in_L"].end(),
                                         [](const json& step) { return step["agree"] == true; });
    result["reason"] =
        (none_agree ? std::string("no L meets the rule: ") : std::string()) +
        "the two smallest mesh-converged L (" + number_text(refs[0].L) + ", " +
        number_text(refs[1].L) + ") already disagree, so L_c is below " + number_text(refs[1].L) +
        " if it exists for this slip event; change of propagation_distance / "
        "arrival_time_at_probe from each L to the next: " +
        describe_steps(result["steps_in_L"]) + "; add smaller L (or plain Coulomb friction)";
    return;
  }
  result["L_c"] = refs[prefix - 1].L;
  if (prefix == refs.size()) {
    result["reason"] = "every mesh-converged L agrees with every smaller one: L_c is at least " +
                       number_text(refs.back().L) + "; add larger L to bound it";
    return;
  }
  result["next_larger_L"] = refs[prefix].L;
  result["reason"] = "L = " + number_text(refs[prefix].L) +
                     " disagrees with a smaller L: L_c lies in [" +
                     number_text(refs[prefix - 1].L) + ", " + number_text(refs[prefix].L) + ")";
}

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

// SPEC §2 "Convergence status of a run".
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
      json cell = cell_json(runs, statuses, L, n_d);
      if (cell.is_null()) continue;
      if (smallest.is_null() && cell["status"] == "converged") smallest = n_d;
      cells.push_back(std::move(cell));
    }
    converged_n_d[json(L).dump()] = smallest;
  }
  return {{"L", Ls}, {"n_d", meshes}, {"cells", cells}, {"converged_n_d", converged_n_d}};
}

// SPEC §2 "Critical length L_c" and the spectral estimate beside it (docs/metrics.md).
nlohmann::json critical_length(const std::vector<StudyRun>& runs,
                               const ConvergenceTolerances& tol) {
  const auto statuses = convergence_statuses(runs, tol);
  std::vector<Reference> refs;
  json excluded = json::array();
  for (double L : study_values(runs, &StudyRun::L)) {
    if (const StudyRun* run = reference_run(runs, statuses, L))
      refs.push_back({L, run});
    else
      excluded.push_back({{"L", L}, {"reason", "no mesh-converged run of this L"}});
  }
  std::vector<std::vector<bool>> agree(refs.size());
  json table = json::array();
  json references = json::array();
  for (std::size_t k = 0; k < refs.size(); ++k) {
    for (std::size_t j = 0; j < k; ++j) {
      const Comparison c = compare(*refs[k].run, *refs[j].run, tol);
      agree[k].push_back(c.agree);
      table.push_back({{"L", refs[k].L},
                       {"smaller_L", refs[j].L},
                       {"agree", c.agree},
                       {"changes", changes_json(c.distance_change, c.arrival_change)},
                       {"reason", c.reason}});
    }
    json ref = reference_json(refs[k].L, *refs[k].run);
    ref["agrees_with_every_smaller_L"] =
        std::all_of(agree[k].begin(), agree[k].end(), [](bool b) { return b; });
    references.push_back(std::move(ref));
  }
  json result = {{"references", references},
                 {"comparisons", table},
                 {"steps_in_L", steps_in_L(refs, tol)},
                 {"excluded", excluded},
                 {"tolerances",
                  {{distance_key, tol.propagation_distance}, {"arrival_time", tol.arrival_time}}}};
  explain_critical_length(result, refs, agreeing_prefix(agree));
  const StudyRun* smallest = refs.empty() ? nullptr : refs.front().run;
  result["spectral_critical_length"] =
      smallest ? json_number(metric(*smallest, "spectral_critical_length")) : json(nullptr);
  result["spectral_from_L"] = smallest ? json(refs.front().L) : json(nullptr);
  result["spectral_run_id"] = smallest ? json(smallest->id) : json(nullptr);
  return result;
}

namespace {

// The runs of one scene by both methods, with each method's reference run of an L.
struct TwoMethods {
  const std::vector<StudyRun>& fe_runs;
  const std::vector<StudyRun>& bi_runs;
  std::vector<RunConvergence> fe_statuses, bi_statuses;

  TwoMethods(const std::vector<StudyRun>& fe, const std::vector<StudyRun>& bi,
             const ConvergenceTolerances& tol)
      : fe_runs(fe), bi_runs(bi), fe_statuses(convergence_statuses(fe, tol)),
        bi_statuses(convergence_statuses(bi, tol)) {}
  const StudyRun* fe_reference(double L) const { return reference_run(fe_runs, fe_statuses, L); }
  const StudyRun* bi_reference(double L) const { return reference_run(bi_runs, bi_statuses, L); }
};

} // namespace

nlohmann::json cross_method_table(const std::vector<StudyRun>& fe_runs,
                                  const std::vector<StudyRun>& bi_runs,
                                  const ConvergenceTolerances& tol) {
  const TwoMethods both(fe_runs, bi_runs, tol);
  std::vector<double> Ls = study_values(fe_runs, &StudyRun::L);
  for (double L : study_values(bi_runs, &StudyRun::L))
    Ls.push_back(L);
  Ls = unique_sorted(Ls);
  // spectral_velocity: the peak |V| at the spectrum probe (x1 = 6 m in the paper's scene).
  const char* keys[] = {"arrest_position", distance_key, arrival_key, "max_slip_velocity",
                        "spectral_velocity"};
  auto side = [&](const StudyRun* run) -> json {
    if (!run) return nullptr;
    json j = {{"run_id", run->id},
              {"n_d", run->n_d},
              {"outcome", outcome_of(*run)},
              {"wall_time_s", json_number(run->wall_time_s)}};
    for (const char* key : keys)
      j[key] = json_number(metric(*run, key));
    return j;
  };
  json rows = json::array();
  for (double L : Ls) {
    const StudyRun* fe = both.fe_reference(L);
    const StudyRun* bi = both.bi_reference(L);
    json row = {{"L", L}, {"fe", side(fe)}, {"spectral_bi", side(bi)}};
    if (fe && bi) {
      json differences;
      for (const char* key : keys) // (fe - bi) / bi
        differences[key] = json_number(relative_change(metric(*fe, key), metric(*bi, key)));
      row["differences"] = differences;
      const Comparison c = compare(*fe, *bi, tol);
      row["agree"] = c.agree;
      row["reason"] = c.reason;
    } else {
      row["differences"] = nullptr;
      row["agree"] = nullptr;
      row["reason"] = std::string("no mesh-converged run of this L by ") + (fe   ? "spectral_bi"
                                                                            : bi ? "fe"
                                                                                 : "either method");
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

// SPEC intro: "every result says how accurate it is and what it cost".
namespace {

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

nlohmann::json speed_accuracy_across_methods(const std::vector<StudyRun>& fe_runs,
                                             const std::vector<StudyRun>& bi_runs,
                                             const ConvergenceTolerances& tol) {
  const TwoMethods both(fe_runs, bi_runs, tol);
  // The reference of an L: the finer of the two methods' references (BI on a tie).
  auto reference_of = [&](double L) -> std::pair<const StudyRun*, const char*> {
    const StudyRun* fe = both.fe_reference(L);
    const StudyRun* bi = both.bi_reference(L);
    if (fe && (!bi || finer(fe->n_d, bi->n_d))) return {fe, "fe"};
    return {bi, bi ? "spectral_bi" : nullptr};
  };
  json list = json::array();
  for (const auto& [runs, method] : {std::pair{&fe_runs, "fe"}, std::pair{&bi_runs, "spectral_bi"}})
    for (const StudyRun& run : *runs) {
      if (!has_result(state_of(run))) continue;
      const auto [ref, ref_method] = reference_of(run.L);
      json entry = speed_accuracy_entry(run, ref);
      entry["method"] = method;
      entry["reference_method"] = ref_method ? json(ref_method) : json(nullptr);
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

// SPEC §2 criterion applied along a mesh ladder: refine until two successive meshes agree.
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
      plan.reason = "n_d = " + number_text(s.n_d) + " is " + of_L[i].status + "; wait for it";
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
