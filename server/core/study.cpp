#include "server/core/study.hpp"

namespace slipfront::server {

api::StudyRun to_study_run(const StudyRunRow& row) {
  api::StudyRun run;
  run.id = row.job_id;
  run.L = row.L;
  run.n_d = row.n_d;
  run.status = api::parse_status(row.job_status).value_or(api::JobStatus::failed);
  if (!row.metrics.is_null()) run.metrics = row.metrics;
  run.wall_time_s = row.wall_time_s;
  if (row.metrics.is_object() && row.metrics.contains("wall_time_s") &&
      row.metrics["wall_time_s"].is_number())
    run.wall_time_s = row.metrics["wall_time_s"].get<double>();
  run.memory_bytes = row.memory_estimate_bytes;
  return run;
}

} // namespace slipfront::server
