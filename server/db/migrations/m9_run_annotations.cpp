// Schema migration 8 -> 9 (server/db/migrations.hpp): what a run's owner keeps with it after
// submission (docs/server.md, "Keep, annotate, share"): a free-text note, the time it was
// archived (NULL = not archived: listed), and for a run imported from another server's
// archive, where it came from (JSON: the original server, id and export time).
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m9_run_annotations() {
  return R"sql(
ALTER TABLE jobs ADD COLUMN note TEXT NOT NULL DEFAULT '';
ALTER TABLE jobs ADD COLUMN archived_at TEXT;
ALTER TABLE jobs ADD COLUMN imported_from TEXT;
CREATE INDEX jobs_result_path ON jobs (result_path);
)sql";
}

} // namespace slipfront::server::migrations
