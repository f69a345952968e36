// Schema migration 7 -> 8 (server/db/migrations.hpp): a study may be of kind `accuracy`
// (docs/studies-api.md "Accuracy target"). SQLite cannot alter a CHECK constraint: the table
// is rebuilt with the same columns, in the same order (foreign keys are off during migrations,
// so study_runs keeps its rows), and its indexes made again.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m8_accuracy_studies() {
  return R"sql(
CREATE TABLE studies_v8 (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  id TEXT NOT NULL UNIQUE,
  name TEXT NOT NULL DEFAULT '',
  tags TEXT NOT NULL DEFAULT '[]',
  kind TEXT NOT NULL CHECK (kind IN ('grid', 'convergence', 'failure_regimes', 'accuracy')),
  base_spec TEXT NOT NULL,
  request TEXT NOT NULL,
  scene_hash TEXT NOT NULL,
  submitted_by TEXT NOT NULL DEFAULT '',
  priority INTEGER NOT NULL DEFAULT 0,
  fresh INTEGER NOT NULL DEFAULT 0,
  created_at TEXT NOT NULL,
  updated_at TEXT,
  finished_at TEXT,
  status TEXT NOT NULL DEFAULT 'running' CHECK (status IN ('running', 'finished', 'cancelled')),
  runs_done INTEGER NOT NULL DEFAULT 0,
  runs_total INTEGER NOT NULL DEFAULT 0,
  L_c REAL,
  spectral_critical_length REAL,
  result TEXT,
  idempotency_key TEXT
);
INSERT INTO studies_v8 SELECT * FROM studies;
DROP TABLE studies;
ALTER TABLE studies_v8 RENAME TO studies;
CREATE INDEX studies_scene_hash ON studies (scene_hash);
CREATE INDEX studies_status ON studies (status);
CREATE UNIQUE INDEX studies_idempotency_key ON studies (submitted_by, idempotency_key)
  WHERE idempotency_key IS NOT NULL;
)sql";
}

} // namespace slipfront::server::migrations
