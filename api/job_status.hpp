// The status of a job (docs/server.md "Job states"): what the server records and the study analysis
// reads.
#pragma once

#include <optional>
#include <string_view>

namespace slipfront::api {

// queued -> running -> succeeded | failed | cancelled; queued -> cancelled.
// Never backwards, with one exception: running -> queued when the server drains on SIGTERM
// or recovers after a crash (the run is restarted from the beginning).
enum class JobStatus { queued, running, succeeded, failed, cancelled };

// "queued", "running", ...: the names of the API.
const char* to_string(JobStatus status);
// The status of a name; nullopt for any other text.
std::optional<JobStatus> parse_status(std::string_view text);
// succeeded, failed or cancelled.
bool is_final(JobStatus status);

} // namespace slipfront::api
