// Schema migration 1 -> 2 (server/db/migrations.hpp): listing by name and by submitter stays fast
// on large tables.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m2_name_and_submitter_indexes() {
  return R"sql(
CREATE INDEX jobs_name ON jobs (name);
CREATE INDEX jobs_submitted_by ON jobs (submitted_by);
)sql";
}

} // namespace slipfront::server::migrations
