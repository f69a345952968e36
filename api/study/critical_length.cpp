// The critical length L_c (docs/metrics.md "Critical length") and the same L by both methods:
// comparisons of the reference runs of mesh-converged L (docs/studies.md).
#include "api/study/critical_length.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "api/study/run_rules.hpp"

#include <algorithm>

namespace slipfront::api {

using namespace study_rules;

namespace {

using nlohmann::json;

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

// The rule of docs/metrics.md "Critical length" read as the paper does (§4: "every simulation with
// L <= L_c obeys the same behaviour"): the number of smallest references that all agree pairwise.
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

} // namespace

// docs/metrics.md "Critical length", and the spectral estimate beside it.
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

nlohmann::json cross_method_table(const MethodRuns& first, const MethodRuns& second,
                                  const ConvergenceTolerances& tol) {
  const TwoMethods both(first, second, tol);
  std::vector<double> Ls = study_values(first.runs, &StudyRun::L);
  for (double L : study_values(second.runs, &StudyRun::L))
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
    const StudyRun* a = both.first_reference(L);
    const StudyRun* b = both.second_reference(L);
    json row = {{"L", L}, {first.method, side(a)}, {second.method, side(b)}};
    if (a && b) {
      json differences;
      for (const char* key : keys) // (a - b) / b
        differences[key] = json_number(relative_change(metric(*a, key), metric(*b, key)));
      row["differences"] = differences;
      const Comparison c = compare(*a, *b, tol);
      row["agree"] = c.agree;
      row["reason"] = c.reason;
    } else {
      row["differences"] = nullptr;
      row["agree"] = nullptr;
      row["reason"] = "no mesh-converged run of this L by " + (a   ? second.method
                                                               : b ? first.method
                                                                   : std::string("either method"));
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

} // namespace slipfront::api
