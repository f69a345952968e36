// Schema migration 0 -> 1 (server/db/migrations.hpp): jobs and metrics.
#include "server/db/migrations/list.hpp"

namespace slipfront::server::migrations {

const char* m1_jobs_and_metrics() {
  return R"sql(
CREATE TABLE jobs (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  id TEXT NOT NULL UNIQUE,
  status TEXT NOT NULL
    CHECK (status IN ('queued', 'running', 'succeeded', 'failed', 'cancelled')),
  name TEXT NOT NULL DEFAULT '',
  tags TEXT NOT NULL DEFAULT '[]',
  spec TEXT NOT NULL,
  spec_sha256 TEXT NOT NULL,
  submitted_by TEXT NOT NULL DEFAULT '',
  idempotency_key TEXT,
  priority INTEGER NOT NULL DEFAULT 0,
  fresh INTEGER NOT NULL DEFAULT 0,
  L REAL,
  n_d REAL,
  memory_estimate_bytes REAL,
  created_at TEXT NOT NULL,
  started_at TEXT,
  finished_at TEXT,
  progress_fraction REAL NOT NULL DEFAULT 0,
  progress_time REAL NOT NULL DEFAULT 0,
  progress_duration REAL NOT NULL DEFAULT 0,
  progress_steps INTEGER NOT NULL DEFAULT 0,
  progress_eta_s REAL,
  progress_updated_at TEXT,
  error TEXT,
  wall_time_s REAL,
  code_version TEXT,
  host TEXT,
  result_path TEXT,
  result_size INTEGER,
  result_sha256 TEXT,
  cached_from TEXT,
  attempts INTEGER NOT NULL DEFAULT 0
);
CREATE INDEX jobs_status ON jobs (status, priority, seq);
CREATE INDEX jobs_reuse ON jobs (spec_sha256, code_version, status);
CREATE UNIQUE INDEX jobs_idempotency ON jobs (submitted_by, idempotency_key)
  WHERE idempotency_key IS NOT NULL;
CREATE INDEX jobs_L_n_d ON jobs (L, n_d);
CREATE TABLE metrics (
  job_id TEXT PRIMARY KEY REFERENCES jobs (id) ON DELETE CASCADE,
  L REAL,
  n_d REAL,
  arrest_position REAL,
  propagation_distance REAL,
  arrival_time_at_probe REAL,
  max_rupture_speed REAL,
  mean_rupture_speed REAL,
  max_slip_velocity REAL,
  outcome TEXT,
  energy_error REAL,
  wall_time_s REAL,
  steps INTEGER,
  dt REAL,
  metrics_json TEXT NOT NULL,
  front_json TEXT
);
CREATE INDEX metrics_outcome ON metrics (outcome);
CREATE INDEX metrics_L_n_d ON metrics (L, n_d);
)sql";
}

} // namespace slipfront::server::migrations
