// Schema migration 6 -> 7 (server/db/migrations.hpp): the Idempotency-Key of POST /studies
// (docs/studies-api.md), unique per submitter as the jobs' is, so that a client that got no
// answer can retry without making a second study.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m7_study_idempotency_keys() {
  return R"sql(
ALTER TABLE studies ADD COLUMN idempotency_key TEXT;
CREATE UNIQUE INDEX studies_idempotency_key ON studies (submitted_by, idempotency_key)
  WHERE idempotency_key IS NOT NULL;
)sql";
}

} // namespace slipfront::server::migrations
