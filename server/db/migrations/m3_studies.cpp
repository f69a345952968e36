// Schema migration 2 -> 3 (server/db/migrations.hpp): studies (docs/studies-api.md).
// jobs.scene_hash (filled for existing rows by fill_scene_hashes() in the same transaction) groups
// the runs of one convergence map; jobs.study_id names the study that submitted a job.
#include "server/db/migrations/list.hpp"

#include "api/job_spec.hpp"
#include "server/db/database.hpp"

#include <string>
#include <utility>
#include <vector>

namespace slipfront::server::migrations {

const char* m3_studies() {
  return R"sql(
ALTER TABLE jobs ADD COLUMN scene_hash TEXT;
ALTER TABLE jobs ADD COLUMN study_id TEXT;
CREATE INDEX jobs_scene_hash ON jobs (scene_hash, status);
CREATE INDEX jobs_study_id ON jobs (study_id);
CREATE TABLE studies (
  seq INTEGER PRIMARY KEY AUTOINCREMENT,
  id TEXT NOT NULL UNIQUE,
  name TEXT NOT NULL DEFAULT '',
  tags TEXT NOT NULL DEFAULT '[]',
  kind TEXT NOT NULL CHECK (kind IN ('grid', 'convergence', 'failure_regimes')),
  base_spec TEXT NOT NULL,
  request TEXT NOT NULL,
  scene_hash TEXT NOT NULL,
  submitted_by TEXT NOT NULL DEFAULT '',
  priority INTEGER NOT NULL DEFAULT 0,
  fresh INTEGER NOT NULL DEFAULT 0,
  created_at TEXT NOT NULL,
  updated_at TEXT,
  finished_at TEXT,
  status TEXT NOT NULL DEFAULT 'running' CHECK (status IN ('running', 'finished')),
  runs_done INTEGER NOT NULL DEFAULT 0,
  runs_total INTEGER NOT NULL DEFAULT 0,
  L_c REAL,
  spectral_critical_length REAL,
  result TEXT
);
CREATE INDEX studies_scene_hash ON studies (scene_hash);
CREATE INDEX studies_status ON studies (status);
CREATE TABLE study_runs (
  study_id TEXT NOT NULL REFERENCES studies (id) ON DELETE CASCADE,
  job_id TEXT NOT NULL REFERENCES jobs (id),
  regime TEXT NOT NULL DEFAULT '',
  L REAL NOT NULL,
  n_d REAL NOT NULL,
  convergence_status TEXT NOT NULL DEFAULT 'pending',
  partner_n_d REAL,
  propagation_distance_change REAL,
  arrival_time_change REAL,
  reason TEXT,
  PRIMARY KEY (study_id, job_id)
);
CREATE INDEX study_runs_job ON study_runs (job_id);
CREATE INDEX study_runs_status ON study_runs (convergence_status);
)sql";
}

void m3_fill_scene_hashes(Database& db) {
  std::vector<std::pair<std::string, std::string>> rows; // id, scene hash
  auto select = db.prepare("SELECT id, spec FROM jobs WHERE scene_hash IS NULL");
  while (select.step()) {
    const std::string id = select.text(0);
    rows.emplace_back(id, api::scene_hash(parse_stored_json(select.text(1), "spec of job " + id)));
  }
  auto update = db.prepare("UPDATE jobs SET scene_hash = ?2 WHERE id = ?1");
  for (const auto& [id, hash] : rows) {
    update.bind(1, id).bind(2, hash).run();
    update.reset();
  }
}

} // namespace slipfront::server::migrations
