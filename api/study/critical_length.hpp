// The critical length L_c of a study (docs/metrics.md "Critical length"), and the same L by both
// methods: comparisons of the reference runs of mesh-converged L (rules: docs/studies.md). Pure
// functions.
#pragma once

#include "api/study/study_run.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace slipfront::api {

// L_c of the study (docs/metrics.md "Critical length") with the per-L reference runs, the
// comparison table and the spectral estimate of the smallest mesh-converged L.
nlohmann::json critical_length(const std::vector<StudyRun>& runs,
                               const ConvergenceTolerances& tol = {});

// The same L by two methods (FE and spectral_bi, in that order): the reference (finest,
// mesh-converged) run of each under its method's name, its metrics, and the relative
// differences (first - second) / second. One row per L of either set; a side is null where
// that method has no mesh-converged run of the L.
nlohmann::json cross_method_table(const MethodRuns& first, const MethodRuns& second,
                                  const ConvergenceTolerances& tol = {});

} // namespace slipfront::api
