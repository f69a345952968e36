// The size of a run's HDF5 result file, estimated at validation (as the memory is), and the
// limit on it: a tiny output interval over a long duration would write hundreds of GB.
#pragma once

#include "api/job_spec.hpp"

#include <vector>

namespace slipfront::api {

// An upper bound, uncompressed (deflate usually makes the file several times smaller):
// every sampled interface field (docs/hdf5-layout.md) at one sample per `output.interval`
// (at most one per step) for the whole duration, the per-step probe and station records and
// the front.
double estimated_result_bytes(const SimulationParams& params);

// Appends an error at "/output/interval" if the estimate exceeds limits.max_result_bytes.
// Call it only for a job without other errors (the estimate assumes a valid job).
void check_result_size(const JobSpec& job, const ValidationLimits& limits,
                       std::vector<FieldError>& errors);

} // namespace slipfront::api
