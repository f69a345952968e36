// An L search (docs/studies-api.md "L search"): a convergence study that is not given its L
// values but walks down from a first L by a factor, refining n_d for each L as any convergence
// study does, until the critical-length rule is met, or a floor, or the mesh cap stops it.
// Pure functions: the server's supervisor asks what to do next.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

struct LSearch {
  double from = 5e-5;  // the first L (m)
  double factor = 2.0; // each next L is the previous one / factor
  double floor = 1e-8; // no L below this one is tried (m)
  int confirm = 2;     // how many smallest L must agree (the paper: L_c and one L below it)
  // Whether plain Coulomb runs of the scene are refined beside the L and compared with them;
  // the service decides when the request does not (where Coulomb is well-posed).
  std::optional<bool> coulomb;
  // What those runs are called in the verdict's text: "plain Coulomb" (the paper's law), or
  // "<law> without regularisation" (the server sets it from the base's law).
  std::string companion = "plain Coulomb";
};

// The plain-Coulomb answer of the search's scene: its mesh-converged reference run, if any.
struct CoulombReference {
  const StudyRun* run = nullptr;
  std::string status; // where it converged, or why there is none
};

// from, from / factor, ... while >= floor (up to round-off), at most max_count values.
std::vector<double> search_ladder(const LSearch& search, std::size_t max_count);

struct SearchVerdict {
  enum class State { refining, next_L, found, meets_coulomb, floor, mesh_cap, all_agree };
  State state = State::refining;
  double next_L = not_available;                  // next_L: the L to add
  double L_c = not_available;                     // found: the critical length
  std::string reason;                             // one paragraph for the reader, with the numbers
  nlohmann::json steps = nlohmann::json::array(); // each searched L against the next smaller
  nlohmann::json coulomb = nullptr; // {status, steps: each searched L against plain Coulomb}
};

std::string to_string(SearchVerdict::State state);

// The plain-Coulomb reference from the search's Coulomb runs (all at friction.L = `L`, which
// Coulomb does not use), refined along `ladder` up to `cap` like any L.
CoulombReference coulomb_reference(double L, const std::vector<StudyRun>& coulomb_runs,
                                   const std::vector<double>& ladder, double cap);

// What the search does next. `ladder` is search_ladder(), `active` how many of its L have
// been started, `settled` whether every started L's mesh refinement has ended (converged or
// not at the cap); `runs` the study's runs. The rule (docs/metrics.md "Critical length"):
// the `confirm` smallest mesh-converged L agree pairwise and a larger one disagrees with
// them: L_c is the largest L of the agreeing group. With a plain-Coulomb reference, the search
// also ends at the first (largest) L whose answer agrees with Coulomb's by the same rule
// (paper Sec. 5: below L_c the rupture propagates as under Coulomb friction): L_c is that L,
// bracketed by the next larger one.
SearchVerdict search_verdict(const LSearch& search, const std::vector<double>& ladder,
                             std::size_t active, bool settled, const std::vector<StudyRun>& runs,
                             const CoulombReference& coulomb = {},
                             const ConvergenceTolerances& tol = {});

} // namespace slipfront::api
