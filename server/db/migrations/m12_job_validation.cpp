// Schema migration 11 -> 12 (server/db/migrations.hpp): what the validation said about a job
// when it was accepted (docs/server.md "Endpoints"): its warnings, where each number with a unit
// came from, and the cost estimate, as one JSON object. NULL for the jobs accepted before.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m12_job_validation() {
  return R"sql(
ALTER TABLE jobs ADD COLUMN validation TEXT;
)sql";
}

} // namespace slipfront::server::migrations
