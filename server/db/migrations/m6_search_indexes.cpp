// Schema migration 5 -> 6 (server/db/migrations.hpp): indexes for the run search
// (GET /api/v1/jobs?where=...&sort=..., server/db/run_query_sql.cpp) on the fields it filters and
// sorts by most. The metrics a search names as metrics.arrest_position,
// metrics.propagation_distance and metrics.arrival_time_at_probe are columns of metrics; the
// search's wall_time_s, created_at and finished_at are columns of jobs (jobs.wall_time_s is
// the one `wall_time_s` reads; metrics.wall_time_s is read from the metrics JSON, so an index
// on the metrics column would not serve it).
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m6_search_indexes() {
  return R"sql(
CREATE INDEX metrics_arrest_position ON metrics (arrest_position);
CREATE INDEX metrics_propagation_distance ON metrics (propagation_distance);
CREATE INDEX metrics_arrival_time_at_probe ON metrics (arrival_time_at_probe);
CREATE INDEX jobs_wall_time_s ON jobs (wall_time_s);
CREATE INDEX jobs_created_at ON jobs (created_at);
CREATE INDEX jobs_finished_at ON jobs (finished_at);
)sql";
}

} // namespace slipfront::server::migrations
