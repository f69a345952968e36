#include "api/job_status.hpp"

namespace slipfront::api {

const char* to_string(JobStatus status) {
  switch (status) {
  case JobStatus::queued:
    return "queued";
  case JobStatus::running:
    return "running";
  case JobStatus::succeeded:
    return "succeeded";
  case JobStatus::failed:
    return "failed";
  case JobStatus::cancelled:
    return "cancelled";
  }
  return "unknown";
}

std::optional<JobStatus> parse_status(std::string_view text) {
  for (JobStatus s : {JobStatus::queued, JobStatus::running, JobStatus::succeeded,
                      JobStatus::failed, JobStatus::cancelled})
    if (text == to_string(s)) return s;
  return std::nullopt;
}

bool is_final(JobStatus status) {
  return status == JobStatus::succeeded || status == JobStatus::failed ||
         status == JobStatus::cancelled;
}

} // namespace slipfront::api
