// The rules the study analyses share (docs/studies.md): what a run contributes, which run
// stands for an (L, n_d) cell, how two runs compare under the convergence criterion, and the
// reference run of an L. Used by api/study/*.cpp only; the server calls the analyses.
#pragma once

#include "api/study/convergence.hpp"
#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace slipfront::api::study_rules {

constexpr const char* distance_key = "propagation_distance";
constexpr const char* arrival_key = "arrival_time_at_probe";

// L and n_d come from JSON numbers: equal up to round-off means the same value.
bool same_value(double a, double b);
// n_d is finer than `than` (and not the same value).
bool finer(double n_d, double than);
// Sorted, each value once (up to same_value).
std::vector<double> unique_sorted(std::vector<double> values);
// "2.8 %": a fraction in percent, three significant digits.
std::string percent(double fraction);

// The metrics' outcome ("" without metrics) and a metric (docs/metrics.md; NaN when absent or
// null).
std::string outcome_of(const StudyRun& run);
double metric(const StudyRun& run, const char* key);

// What a run contributes. The server stores a diverged run as job status "failed" with
// metrics outcome "diverged" (server/run/job_runner.cpp): it is a result, not a void run.
// A cancelled run, and one whose metrics say it took 0 steps or simulated no time, is void.
enum class RunState { measured, diverged, pending, void_run };
RunState state_of(const StudyRun& run);
bool has_result(RunState state);

// The run that stands for an (L, n_d) cell: a result before a pending run before a void
// one; among equals the smallest id (deterministic for duplicate submissions).
const StudyRun* pick_run(const std::vector<StudyRun>& runs, double L, double n_d);

// |value - reference| / |reference|; NaN if either is undefined.
double relative_change(double value, double reference);

struct Comparison {
  bool agree = false;
  double distance_change = not_available;
  double arrival_change = not_available;
  std::string reason;
};

// Where both fronts arrived: a station of both runs' metrics with its two rupture times.
struct StationArrival {
  double x1 = 0.0;
  double time = not_available;           // the run's rupture time there
  double reference_time = not_available; // the reference's
};
std::optional<StationArrival> common_station(const StudyRun& run, const StudyRun& reference);

// The convergence criterion (docs/metrics.md "Convergence status") between a run and its
// reference (the finer mesh, or the smaller L).
Comparison compare(const StudyRun& run, const StudyRun& reference,
                   const ConvergenceTolerances& tol);

// The distinct values of one field (L or n_d) over the runs, sorted.
std::vector<double> study_values(const std::vector<StudyRun>& runs, double StudyRun::*field);

// The reference run of an L: its finest run with a non-diverged result, provided the L has
// at least one mesh-converged run; otherwise none.
const StudyRun* reference_run(const std::vector<StudyRun>& runs,
                              const std::vector<RunConvergence>& statuses, double L);

// {"propagation_distance": change, "arrival_time": change}, null where undefined.
nlohmann::json changes_json(double distance_change, double arrival_change);

// The runs of one scene by two methods (in the registry's order: FE first, then the spectral
// BI method), with each method's reference run of an L.
struct TwoMethods {
  const MethodRuns& first;
  const MethodRuns& second;
  std::vector<RunConvergence> first_statuses, second_statuses;

  TwoMethods(const MethodRuns& a, const MethodRuns& b, const ConvergenceTolerances& tol)
      : first(a), second(b), first_statuses(convergence_statuses(a.runs, tol)),
        second_statuses(convergence_statuses(b.runs, tol)) {}
  const StudyRun* first_reference(double L) const {
    return reference_run(first.runs, first_statuses, L);
  }
  const StudyRun* second_reference(double L) const {
    return reference_run(second.runs, second_statuses, L);
  }
};

} // namespace slipfront::api::study_rules
