// Speed and accuracy of the runs of a study (SPEC intro: "every result says how accurate it
// is and what it cost"): cost against the errors relative to the reference run of each L,
// and the relative L2 error of a time record (docs/studies.md). Pure functions.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace slipfront::api {

// Per finished run: cost and errors relative to the reference run of its L.
nlohmann::json speed_accuracy(const std::vector<StudyRun>& runs,
                              const ConvergenceTolerances& tol = {});

// As speed_accuracy, over the runs of both methods of one scene: each entry names its
// "method", and its errors are against the finest reference run of its L by either method
// (spectral_bi on a tie), named by "reference_run_id" and "reference_method".
nlohmann::json speed_accuracy_across_methods(const std::vector<StudyRun>& fe_runs,
                                             const std::vector<StudyRun>& bi_runs,
                                             const ConvergenceTolerances& tol = {});

// ||v_a - v_ref|| / ||v_ref|| in L2 over time, on the samples of `a` that lie in the common
// time range; the reference is interpolated linearly onto them (trapezoidal rule).
// NaN when fewer than two samples of `a` lie in the common range or ||v_ref|| = 0.
// Throws std::invalid_argument on size mismatch or times that do not increase.
double relative_l2_error(const std::vector<double>& t_a, const std::vector<double>& v_a,
                         const std::vector<double>& t_ref, const std::vector<double>& v_ref);

} // namespace slipfront::api
