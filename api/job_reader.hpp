// The mapping between the job JSON (docs/api-job-spec.md) and SimulationParams:
// which member fills which parameter, with its type and allowed range.
#pragma once

#include "api/job_spec.hpp"
#include "api/json_fields.hpp"

namespace slipfront::api {

// Reads every known field of the document into `job` (params, name, tags) and the
// canonical form into `reader`; type and range errors go to the reader's error list.
void read_job_fields(ObjectReader& reader, JobSpec& job);

} // namespace slipfront::api
