// Schema migration 10 -> 11 (server/db/migrations.hpp): who imported the result file a row
// refers to (NULL: this server computed it). An imported run, and every cache hit of it, keeps
// its importer here: such a result is a cache source for its importer only, never for another
// user, since its archive may have been edited and re-signed (docs/server.md "Export and import").
// Rows imported before: their importer is the submitter of the imported row of their file.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m11_imported_results() {
  return R"sql(
ALTER TABLE jobs ADD COLUMN result_imported_by TEXT;
UPDATE jobs SET result_imported_by = (
  SELECT i.submitted_by FROM jobs i
  WHERE i.result_path = jobs.result_path AND i.imported_from IS NOT NULL
  ORDER BY i.seq LIMIT 1)
WHERE result_path IS NOT NULL;
)sql";
}

} // namespace slipfront::server::migrations
