// Checks of a job that involve several fields at once (mesh sizes, probe positions, the
// initial stuck state) and the memory limit. They run after every field was read; a check
// whose fields already have an error of their own is skipped.
#pragma once

#include "api/job_spec.hpp"

#include <vector>

namespace slipfront::api {

void check_job_consistency(const JobSpec& job, std::vector<FieldError>& errors);

// Appends an error at "/geometry/nodes_per_meter" if the memory estimate exceeds the limit.
// Call it only for a job without other errors (the estimate assumes a valid job).
void check_memory(const JobSpec& job, const ValidationLimits& limits,
                  std::vector<FieldError>& errors);

} // namespace slipfront::api
