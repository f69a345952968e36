#include "server/core/job.hpp"

namespace slipfront::server {

bool transition_allowed(JobStatus from, JobStatus to, TransitionKind kind) {
  switch (from) {
  case JobStatus::queued:
    return to == JobStatus::running || to == JobStatus::cancelled;
  case JobStatus::running:
    if (to == JobStatus::queued) return kind == TransitionKind::recovery;
    return is_final(to);
  default:
    return false;
  }
}

} // namespace slipfront::server
