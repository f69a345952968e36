// The L search (docs/studies-api.md "L search"): which L comes next, and when the search ends.
#include "api/study/l_search.hpp"

#include "api/json_number.hpp"
#include "api/number_text.hpp"
#include "api/study/convergence.hpp"
#include "api/study/run_rules.hpp"

namespace slipfront::api {

using nlohmann::json;
using namespace study_rules;

std::vector<double> search_ladder(const LSearch& search, std::size_t max_count) {
  std::vector<double> ladder;
  double L = search.from;
  while (ladder.size() < max_count && (L >= search.floor || same_value(L, search.floor))) {
    ladder.push_back(L);
    L /= search.factor;
  }
  return ladder;
}

std::string to_string(SearchVerdict::State state) {
  switch (state) {
  case SearchVerdict::State::refining:
    return "refining";
  case SearchVerdict::State::next_L:
    return "next_L";
  case SearchVerdict::State::found:
    return "found";
  case SearchVerdict::State::meets_coulomb:
    return "meets_coulomb";
  case SearchVerdict::State::floor:
    return "floor";
  case SearchVerdict::State::mesh_cap:
    return "mesh_cap";
  case SearchVerdict::State::all_agree:
    return "all_agree";
  }
  return "refining";
}

CoulombReference coulomb_reference(double L, const std::vector<StudyRun>& coulomb_runs,
                                   const std::vector<double>& ladder, double cap) {
  CoulombReference ref;
  const auto plan = refinement_plan(L, coulomb_runs, ladder, cap);
  ref.run = reference_run(coulomb_runs, convergence_statuses(coulomb_runs), L);
  ref.status = ref.run ? "mesh-converged from n_d = " + number_text(plan.converged_n_d) +
                             ", compared at n_d = " + number_text(ref.run->n_d)
                       : to_string(plan.state) + ": " + plan.reason;
  return ref;
}

namespace {

struct Reference {
  double L;
  const StudyRun* run;
};

std::string list_text(const std::vector<Reference>& refs, std::size_t first, std::size_t end) {
  std::string text;
  for (std::size_t i = first; i < end; ++i)
    text += (text.empty() ? "" : ", ") + number_text(refs[i].L);
  return text;
}

// How many of the smallest references (refs in decreasing L) agree pairwise.
std::size_t agreeing_tail(const std::vector<Reference>& refs, const ConvergenceTolerances& tol) {
  std::size_t group = refs.empty() ? 0 : 1;
  while (group < refs.size()) {
    const Reference& candidate = refs[refs.size() - 1 - group];
    bool all = true;
    for (std::size_t j = refs.size() - group; j < refs.size(); ++j)
      all = all && compare(*candidate.run, *refs[j].run, tol).agree;
    if (!all) break;
    ++group;
  }
  return group;
}

} // namespace

SearchVerdict search_verdict(const LSearch& search, const std::vector<double>& ladder,
                             std::size_t active, bool settled, const std::vector<StudyRun>& runs,
                             const CoulombReference& coulomb, const ConvergenceTolerances& tol) {
  SearchVerdict v;
  active = std::min(active, ladder.size());
  const auto statuses = convergence_statuses(runs, tol);
  std::vector<Reference> refs; // the started L with a mesh-converged run, decreasing
  std::size_t unconverged_tail = 0;
  for (std::size_t i = 0; i < active; ++i) {
    if (const StudyRun* run = reference_run(runs, statuses, ladder[i])) {
      refs.push_back({ladder[i], run});
      unconverged_tail = 0;
    } else {
      ++unconverged_tail;
    }
  }
  for (std::size_t k = 0; k + 1 < refs.size(); ++k) {
    const Comparison c = compare(*refs[k].run, *refs[k + 1].run, tol);
    v.steps.push_back({{"L", refs[k].L},
                       {"smaller_L", refs[k + 1].L},
                       {"agree", c.agree},
                       {"changes", changes_json(c.distance_change, c.arrival_change)},
                       {"reason", c.reason}});
  }
  // Each mesh-converged L against plain Coulomb; the first (largest) that agrees.
  std::size_t meets = refs.size();
  if (search.coulomb.value_or(false)) {
    json against = json::array();
    for (std::size_t k = 0; coulomb.run && k < refs.size(); ++k) {
      const Comparison c = compare(*refs[k].run, *coulomb.run, tol);
      against.push_back({{"L", refs[k].L},
                         {"agree", c.agree},
                         {"changes", changes_json(c.distance_change, c.arrival_change)},
                         {"reason", c.reason}});
      if (c.agree && meets == refs.size()) meets = k;
    }
    v.coulomb = {{"status", coulomb.status}, {"steps", against}};
  }
  if (!settled) {
    v.reason =
        "refining the meshes of L = " + number_text(ladder[active - 1]) +
        (search.coulomb.value_or(false) && !coulomb.run ? " (and of " + search.companion + ")"
                                                        : std::string());
    return v;
  }
  const std::size_t confirm = static_cast<std::size_t>(search.confirm);
  const std::size_t group = agreeing_tail(refs, tol);
  if (group >= confirm && group < refs.size()) {
    const std::size_t first = refs.size() - group;
    v.state = SearchVerdict::State::found;
    v.L_c = refs[first].L;
    v.reason = "the critical-length rule is met: the " + std::to_string(group) +
               " smallest mesh-converged L (" + list_text(refs, first, refs.size()) +
               ") agree pairwise, and L = " + number_text(refs[first - 1].L) +
               " disagrees with them (" +
               compare(*refs[first - 1].run, *refs[first].run, tol).reason +
               "): L_c = " + number_text(v.L_c) + ", in [" + number_text(v.L_c) + ", " +
               number_text(refs[first - 1].L) + ")";
    return v;
  }
  if (meets < refs.size()) {
    v.state = SearchVerdict::State::meets_coulomb;
    v.L_c = refs[meets].L;
    v.reason = "L = " + number_text(v.L_c) + " meets " + search.companion + " (" +
               compare(*refs[meets].run, *coulomb.run, tol).reason + "; " + search.companion +
               ": " + coulomb.status + "): below L_c the rupture propagates as with " +
               search.companion + ", so " +
               (meets > 0 ? "L_c = " + number_text(v.L_c) + ", in [" + number_text(v.L_c) + ", " +
                                number_text(refs[meets - 1].L) + ")"
                          : "L_c is at least " + number_text(v.L_c) +
                                " (start the search at a larger L to bound it)");
    return v;
  }
  if (unconverged_tail >= confirm) {
    v.state = SearchVerdict::State::mesh_cap;
    v.reason = "stopped at the mesh cap: the " + std::to_string(unconverged_tail) +
               " smallest L tried (down to " + number_text(ladder[active - 1]) +
               ") have no two successive meshes that agree up to the study's n_d cap, so "
               "smaller L cannot be judged with these meshes" +
               (refs.empty() ? std::string()
                             : "; the smallest mesh-converged L is " + number_text(refs.back().L));
    return v;
  }
  if (active < ladder.size()) {
    v.state = SearchVerdict::State::next_L;
    v.next_L = ladder[active];
    v.reason = "the rule is not met yet (" + std::to_string(group) + " of " +
               std::to_string(confirm) + " smallest L agree" +
               (group == refs.size() && !refs.empty() ? ", and no larger L disagrees yet" : "") +
               "): next L = " + number_text(v.next_L);
    return v;
  }
  if (group >= confirm) {
    v.state = SearchVerdict::State::all_agree;
    v.L_c = refs.front().L;
    v.reason = "every mesh-converged L from " + number_text(refs.front().L) +
               " down to the floor " + number_text(refs.back().L) +
               " agrees with every smaller one: L_c is at least " + number_text(v.L_c) +
               " (start the search at a larger L to bound it)";
    return v;
  }
  v.state = SearchVerdict::State::floor;
  v.reason =
      "reached the floor L = " + number_text(ladder.back()) + " without meeting the rule: " +
      (refs.size() < 2 ? "fewer than two mesh-converged L"
                       : "the smallest mesh-converged L (" +
                             list_text(refs, refs.size() - 2, refs.size()) + ") still disagree") +
      "; L_c is below the floor if it exists for this slip event";
  return v;
}

} // namespace slipfront::api
