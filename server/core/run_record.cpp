#include "server/core/run_record.hpp"

namespace slipfront::server {

RunRecord failed_run(const std::string& reason) {
  RunRecord record;
  record.status = JobStatus::failed;
  record.error = reason;
  return record;
}

RunRecord cancelled_run(const std::string& cancelled_by) {
  RunRecord record;
  record.status = JobStatus::cancelled;
  record.error = "cancelled while running" + (cancelled_by.empty() ? "" : " by " + cancelled_by);
  return record;
}

} // namespace slipfront::server
