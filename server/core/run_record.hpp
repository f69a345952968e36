// The run record (api/run_record.hpp): what a finished run leaves behind, the one shape of a
// run's result between the runners (server/run/: local and SLURM) and the store
// (server/db/job_store.hpp, which derives the metrics row from its metrics), and the records
// of the runs that leave nothing behind but why.
#pragma once

#include "api/run_record.hpp"
#include "server/core/job.hpp"

#include <string>

namespace slipfront::server {

using api::RunRecord;

// A run that could not be carried out: failed with `reason`, nothing else kept.
RunRecord failed_run(const std::string& reason);

// A run the API cancelled while it ran ("cancelled while running by <user>"): nothing kept.
RunRecord cancelled_run(const std::string& cancelled_by);

} // namespace slipfront::server
