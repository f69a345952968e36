// Schema migration 12 -> 13 (server/db/migrations.hpp): what a study's owner keeps with it
// (docs/server.md "Keep, annotate, share"): a free-text note and the time it was archived
// (NULL: listed). Its tags were there from the start.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m13_study_annotations() {
  return R"sql(
ALTER TABLE studies ADD COLUMN note TEXT NOT NULL DEFAULT '';
ALTER TABLE studies ADD COLUMN archived_at TEXT;
)sql";
}

} // namespace slipfront::server::migrations
