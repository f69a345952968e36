// Schema migration 9 -> 10 (server/db/migrations.hpp): the result files a change of several
// steps is about to create or remove (an import: files linked into results/, then its rows;
// a delete: the row, then its file), written and committed before the files are touched and
// removed with the change's last step. Start-up removes every file an intent names that no
// row refers to, so a crash in between leaves no file without a row (docs/reliability.md).
// `paths`: a JSON array of result paths relative to the data dir.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m10_file_intents() {
  return R"sql(
CREATE TABLE file_intents (
  id INTEGER PRIMARY KEY,
  kind TEXT NOT NULL CHECK (kind IN ('import', 'delete')),
  paths TEXT NOT NULL,
  created_at TEXT NOT NULL
);
)sql";
}

} // namespace slipfront::server::migrations
