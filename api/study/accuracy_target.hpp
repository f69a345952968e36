// Answers at a stated accuracy (docs/studies-api.md "Accuracy target"): a study that is given
// one metric and the relative error it may have, refines the mesh of one L along a ladder and
// stops as soon as the error estimate of its finest run meets the target. Pure functions: the
// server's supervisor asks what to do next.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace slipfront::api {

struct AccuracyTarget {
  std::string metric;       // one of accuracy_metrics() (docs/metrics.md names)
  double tolerance = 0.0;   // the relative error allowed, e.g. 0.005 for 0.5 %
  double L = not_available; // friction.L of the runs (m); NaN for a law without L
};

// The metrics a target may name; "rupture_speed.max" reads the member of the metrics' object.
const std::vector<std::string>& accuracy_metrics();
// The metrics measured at interface nodes: their value moves in steps of dx, so no estimate
// is below the finest run's node spacing 1/n_d (docs/metrics.md "The slip front").
bool is_node_quantised(const std::string& metric);
// The metric of a run by its dotted name; NaN when absent or null.
double accuracy_metric(const StudyRun& run, const std::string& metric);

struct AccuracyVerdict {
  enum class State { waiting, run_next, met, mesh_cap, failed };
  State state = State::waiting;
  double next_n_d = not_available; // run_next: the mesh to submit
  double value = not_available;    // the finest run's value of the metric
  double error = not_available;    // its estimated absolute error
  double relative_error = not_available;
  double n_d = not_available;            // the mesh of `value`
  std::string estimate;                  // "last refinement", "Richardson" or "node spacing"
  double observed_order = not_available; // Richardson: p from the last three meshes
  double extrapolated = not_available;   // Richardson: the extrapolated value
  std::string reason;                    // one paragraph with the numbers
  nlohmann::json steps = nlohmann::json::array(); // each mesh: n_d, value, change, estimate
};

std::string to_string(AccuracyVerdict::State state);

// What the study does next. `ladder` the meshes in increasing order, `first` the index of
// the ladder's first mesh the study runs (accuracy_start), `n_d_max` the cap. The estimate of
// the finest of two successive meshes (coarse value a, fine value b, ratio r = n_fine /
// n_coarse): with three meshes whose changes shrink, Richardson with the observed order p,
// |b - a| / (r^p - 1) (p clamped to [0.5, 4]); otherwise |b - a| (exact for first order at
// r = 2, conservative above it); never below 1/n_d for a node-quantised metric.
AccuracyVerdict accuracy_verdict(const AccuracyTarget& target, const std::vector<double>& ladder,
                                 std::size_t first, double n_d_max,
                                 const std::vector<StudyRun>& runs);

// Where the ladder starts, from the runs the shared database already has of the same scene
// and L (the convergence map): past every successive pair of meshes whose estimate did not
// meet the target, so the known-too-coarse meshes are skipped. `why` says what decided.
std::size_t accuracy_start(const AccuracyTarget& target, const std::vector<double>& ladder,
                           double n_d_max, const std::vector<StudyRun>& scene_runs,
                           std::string& why);

nlohmann::json to_json(const AccuracyVerdict& verdict);

} // namespace slipfront::api
