#include "server/job_store.hpp"

#include "api/job_spec.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <variant>

namespace slipfront::server {

const std::vector<std::string>& schema_migrations() {
  static const std::vector<std::string> migrations = {
      // 0 -> 1: jobs and metrics.
      R"sql(
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
)sql",
      // 1 -> 2: listing by name and by submitter stays fast on large tables.
      R"sql(
CREATE INDEX jobs_name ON jobs (name);
CREATE INDEX jobs_submitted_by ON jobs (submitted_by);
)sql",
      // 2 -> 3: studies (docs/studies-api.md). jobs.scene_hash (filled for existing rows by
      // fill_scene_hashes() in the same transaction) groups the runs of one convergence map;
      // jobs.study_id names the study that submitted a job.
      R"sql(
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
)sql",
      // 3 -> 4: a study can be `cancelled` (POST /studies/{id}/cancel). SQLite cannot alter
      // a CHECK constraint: the table is rebuilt with the same columns, in the same order
      // (foreign keys are off during migrations, so study_runs keeps its rows).
      R"sql(
CREATE TABLE studies_v4 (
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
  status TEXT NOT NULL DEFAULT 'running' CHECK (status IN ('running', 'finished', 'cancelled')),
  runs_done INTEGER NOT NULL DEFAULT 0,
  runs_total INTEGER NOT NULL DEFAULT 0,
  L_c REAL,
  spectral_critical_length REAL,
  result TEXT
);
INSERT INTO studies_v4 SELECT * FROM studies;
DROP TABLE studies;
ALTER TABLE studies_v4 RENAME TO studies;
CREATE INDEX studies_scene_hash ON studies (scene_hash);
CREATE INDEX studies_status ON studies (status);
)sql",
      // 4 -> 5: the executor that ran (or runs) a job, and its SLURM job while it is in
      // SLURM: the server re-attaches to it after a restart instead of running it again.
      R"sql(
ALTER TABLE jobs ADD COLUMN executor TEXT;
ALTER TABLE jobs ADD COLUMN slurm_job_id TEXT;
ALTER TABLE jobs ADD COLUMN slurm_state TEXT;
CREATE INDEX jobs_slurm ON jobs (status, slurm_job_id);
)sql",
  };
  return migrations;
}

namespace {

const char* job_columns =
    "j.seq, j.id, j.status, j.name, j.tags, j.spec, j.spec_sha256, j.submitted_by, "
    "j.idempotency_key, j.priority, j.fresh, j.L, j.n_d, j.memory_estimate_bytes, j.created_at, "
    "j.started_at, j.finished_at, j.progress_fraction, j.progress_time, j.progress_duration, "
    "j.progress_steps, j.progress_eta_s, j.progress_updated_at, j.error, j.wall_time_s, "
    "j.code_version, j.host, j.result_path, j.result_size, j.result_sha256, j.cached_from, "
    "j.attempts, m.metrics_json, j.scene_hash, j.study_id, j.executor, j.slurm_job_id, "
    "j.slurm_state";

const char* job_from = " FROM jobs j LEFT JOIN metrics m ON m.job_id = j.id ";

Job read_job(const Statement& s) {
  Job job;
  job.seq = s.integer(0);
  job.id = s.text(1);
  auto status = parse_status(s.text(2));
  if (!status) throw std::runtime_error("job " + job.id + " has unknown status " + s.text(2));
  job.status = *status;
  job.name = s.text(3);
  job.tags = parse_stored_json(s.text(4), "tags of job " + job.id).get<std::vector<std::string>>();
  job.spec = parse_stored_json(s.text(5), "spec of job " + job.id);
  job.spec_sha256 = s.text(6);
  job.submitted_by = s.text(7);
  job.idempotency_key = s.text(8);
  job.priority = static_cast<int>(s.integer(9));
  job.fresh = s.integer(10) != 0;
  job.L = s.real(11);
  job.n_d = s.real(12);
  job.memory_estimate_bytes = s.real(13);
  job.created_at = s.text(14);
  job.started_at = s.text(15);
  job.finished_at = s.text(16);
  job.progress.fraction = s.real(17);
  job.progress.time = s.real(18);
  job.progress.duration = s.real(19);
  job.progress.steps = s.integer(20);
  job.progress.eta_s = s.real(21);
  job.progress.updated_at = s.text(22);
  job.error = s.text(23);
  job.wall_time_s = s.real(24);
  job.code_version = s.text(25);
  job.host = s.text(26);
  job.result.path = s.text(27);
  job.result.size = static_cast<std::uint64_t>(s.integer(28));
  job.result.sha256 = s.text(29);
  job.cached_from = s.text(30);
  job.attempts = static_cast<int>(s.integer(31));
  job.metrics = parse_stored_json(s.text(32), "metrics of job " + job.id);
  job.scene_hash = s.text(33);
  job.study_id = s.text(34);
  job.executor = s.text(35);
  job.slurm_job_id = s.text(36);
  job.slurm_state = s.text(37);
  return job;
}

std::optional<double> metric(const nlohmann::json& metrics, const char* key,
                             const char* nested = nullptr) {
  if (!metrics.is_object()) return std::nullopt;
  auto it = metrics.find(key);
  if (it == metrics.end()) return std::nullopt;
  if (nested) {
    if (!it->is_object()) return std::nullopt;
    auto inner = it->find(nested);
    if (inner == it->end() || !inner->is_number()) return std::nullopt;
    return inner->get<double>();
  }
  if (!it->is_number()) return std::nullopt;
  double v = it->get<double>();
  if (!std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<double> either(std::optional<double> a, std::optional<double> b) {
  return a ? a : b;
}

} // namespace

void fill_scene_hashes(Database& db) {
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

namespace {
// Before SQLite opens it: an empty file would be taken as a new, empty database.
const std::string& refuse_empty_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) == 0 && !ec)
    throw std::runtime_error("database " + path +
                             " is an empty file (truncated?): refusing to start on it as on a "
                             "new database. Restore it from a backup (docs/server.md, Backups), "
                             "or delete it to start with an empty database");
  return path;
}

void check_integrity(Database& db) {
  std::string report;
  try {
    auto s = db.prepare("PRAGMA quick_check");
    while (s.step()) {
      if (!report.empty()) report += "; ";
      report += s.text(0);
      if (report.size() > 400) break;
    }
  } catch (const SqliteError& e) {
    report = e.what();
  }
  if (report != "ok")
    throw std::runtime_error("database " + db.path() +
                             " is damaged (PRAGMA quick_check: " + report +
                             "): refusing to start on it. Restore it from a backup "
                             "(docs/server.md, Backups); --integrity-check off starts anyway");
}
} // namespace

JobStore::JobStore(const std::string& path, bool integrity_check) : db_(refuse_empty_file(path)) {
  if (integrity_check) check_integrity(db_);
  db_.exec("PRAGMA busy_timeout = 5000");
  db_.exec("PRAGMA journal_mode = WAL");
  db_.exec("PRAGMA synchronous = FULL");
  migrate(); // with foreign keys off: a migration may rebuild a referenced table
  db_.exec("PRAGMA foreign_keys = ON");
  probe_db_.emplace(path);
  probe_db_->exec("PRAGMA busy_timeout = 1000");
}

JobStore::~JobStore() {
  std::lock_guard lock(mutex_);
  try {
    db_.exec("PRAGMA wal_checkpoint(TRUNCATE)");
  } catch (const std::exception&) { // the data is safe in the WAL; the next open replays it
  }
}

std::int64_t JobStore::user_version() {
  std::lock_guard lock(probe_mutex_);
  return probe_db_->user_version();
}

void JobStore::migrate() {
  const auto& migrations = schema_migrations();
  auto version = db_.user_version();
  if (version > static_cast<std::int64_t>(migrations.size()))
    throw std::runtime_error("database " + db_.path() + " has schema version " +
                             std::to_string(version) + ", newer than this build's " +
                             std::to_string(migrations.size()) + ": upgrade slipfront");
  for (auto v = version; v < static_cast<std::int64_t>(migrations.size()); ++v) {
    Transaction tx(db_);
    try {
      db_.exec(migrations[static_cast<std::size_t>(v)]);
    } catch (const std::exception& e) {
      throw std::runtime_error("migrating " + db_.path() + " from schema version " +
                               std::to_string(v) + ": " + e.what());
    }
    if (v + 1 == 3) fill_scene_hashes(db_);
    {
      auto check = db_.prepare("PRAGMA foreign_key_check");
      if (check.step())
        throw std::runtime_error("migrating " + db_.path() + " to schema version " +
                                 std::to_string(v + 1) + ": a foreign key of table " +
                                 check.text(0) + " no longer holds");
    }
    db_.set_user_version(v + 1);
    tx.commit();
  }
}

std::int64_t JobStore::insert(const Job& job) {
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  auto s = db_.prepare(
      "INSERT INTO jobs (id, status, name, tags, spec, spec_sha256, submitted_by, "
      "idempotency_key, priority, fresh, L, n_d, memory_estimate_bytes, created_at, started_at, "
      "finished_at, progress_fraction, progress_time, progress_duration, progress_steps, "
      "progress_updated_at, error, wall_time_s, code_version, host, result_path, result_size, "
      "result_sha256, cached_from, scene_hash, study_id) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, "
      "?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, ?19, ?20, ?21, ?22, ?23, ?24, ?25, ?26, "
      "?27, ?28, ?29, ?30, ?31)");
  auto opt = [](const std::string& v) {
    return v.empty() ? std::nullopt : std::optional<std::string>(v);
  };
  s.bind(1, job.id)
      .bind(2, std::string(to_string(job.status)))
      .bind(3, job.name)
      .bind(4, nlohmann::json(job.tags).dump())
      .bind(5, job.spec.dump())
      .bind(6, job.spec_sha256)
      .bind(7, job.submitted_by)
      .bind(8, opt(job.idempotency_key))
      .bind(9, std::int64_t{job.priority})
      .bind(10, std::int64_t{job.fresh ? 1 : 0})
      .bind(11, job.L)
      .bind(12, job.n_d)
      .bind(13, job.memory_estimate_bytes)
      .bind(14, job.created_at)
      .bind(15, opt(job.started_at))
      .bind(16, opt(job.finished_at))
      .bind(17, job.progress.fraction)
      .bind(18, job.progress.time)
      .bind(19, job.progress.duration)
      .bind(20, job.progress.steps)
      .bind(21, opt(job.progress.updated_at))
      .bind(22, opt(job.error))
      .bind(23, job.wall_time_s)
      .bind(24, opt(job.code_version))
      .bind(25, opt(job.host))
      .bind(26, opt(job.result.path))
      .bind(27, static_cast<std::int64_t>(job.result.size))
      .bind(28, opt(job.result.sha256))
      .bind(29, opt(job.cached_from))
      .bind(30, opt(job.scene_hash))
      .bind(31, opt(job.study_id));
  s.run();
  auto seq = db_.last_insert_rowid();
  if (!job.cached_from.empty()) {
    auto copy = db_.prepare(
        "INSERT INTO metrics (job_id, L, n_d, arrest_position, propagation_distance, "
        "arrival_time_at_probe, max_rupture_speed, mean_rupture_speed, max_slip_velocity, "
        "outcome, energy_error, wall_time_s, steps, dt, metrics_json, front_json) "
        "SELECT ?1, L, n_d, arrest_position, propagation_distance, arrival_time_at_probe, "
        "max_rupture_speed, mean_rupture_speed, max_slip_velocity, outcome, energy_error, "
        "wall_time_s, steps, dt, metrics_json, front_json FROM metrics WHERE job_id = ?2");
    copy.bind(1, job.id).bind(2, job.cached_from).run();
  }
  tx.commit();
  return seq;
}

std::optional<Job> JobStore::query_one(const std::string& where,
                                       const std::vector<std::string>& args) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string("SELECT ") + job_columns + job_from + where);
  for (std::size_t i = 0; i < args.size(); ++i)
    s.bind(static_cast<int>(i + 1), args[i]);
  if (!s.step()) return std::nullopt;
  return read_job(s);
}

std::optional<Job> JobStore::get(const std::string& id) {
  return query_one("WHERE j.id = ?1", {id});
}

std::optional<Job> JobStore::find_by_idempotency_key(const std::string& user,
                                                     const std::string& key) {
  return query_one("WHERE j.submitted_by = ?1 AND j.idempotency_key = ?2", {user, key});
}

std::optional<Job> JobStore::find_reusable(const std::string& spec_sha256,
                                           const std::string& code_version,
                                           const nlohmann::json& output) {
  // Both sides of the output comparison are nlohmann dumps (keys sorted, shortest round-trip
  // numbers) and SQLite's json() keeps number tokens as written, so equal text is equal
  // settings. A spec without `output` compares as null.
  return query_one("WHERE j.spec_sha256 = ?1 AND j.code_version = ?2 AND j.status = 'succeeded' "
                   "AND j.result_path IS NOT NULL AND m.job_id IS NOT NULL "
                   "AND ifnull(json_extract(j.spec, '$.output'), 'null') = json(?3) "
                   "ORDER BY j.seq DESC LIMIT 1",
                   {spec_sha256, code_version, output.dump()});
}

bool JobStore::mark_running(const std::string& id, const std::string& started_at,
                            const std::string& host, const std::string& code_version,
                            const std::string& executor) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("UPDATE jobs SET status = 'running', started_at = ?2, host = ?3, "
                       "code_version = ?4, attempts = attempts + 1, progress_updated_at = ?2, "
                       "executor = ?5, slurm_job_id = NULL, slurm_state = NULL "
                       "WHERE id = ?1 AND status = 'queued'");
  s.bind(1, id).bind(2, started_at).bind(3, host).bind(4, code_version).bind(5, executor).run();
  return s.changes() == 1;
}

bool JobStore::set_slurm_job(const std::string& id, const std::string& slurm_job_id,
                             const std::string& slurm_state) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("UPDATE jobs SET slurm_job_id = ?2, slurm_state = ?3 "
                       "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).bind(2, slurm_job_id).bind(3, slurm_state).run();
  return s.changes() == 1;
}

void JobStore::update_slurm_state(const std::string& id, const std::string& slurm_state,
                                  const std::string& host) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("UPDATE jobs SET slurm_state = ?2, host = COALESCE(?3, host) "
                       "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).bind(2, slurm_state);
  if (host.empty())
    s.bind_null(3);
  else
    s.bind(3, host);
  s.run();
}

std::vector<Job> JobStore::running_slurm_jobs() {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string("SELECT ") + job_columns + job_from +
                       "WHERE j.status = 'running' AND j.slurm_job_id IS NOT NULL "
                       "ORDER BY j.seq ASC");
  std::vector<Job> jobs;
  while (s.step())
    jobs.push_back(read_job(s));
  return jobs;
}

void JobStore::update_progress(const std::string& id, const JobProgress& p) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("UPDATE jobs SET progress_fraction = ?2, progress_time = ?3, "
                       "progress_duration = ?4, progress_steps = ?5, progress_eta_s = ?6, "
                       "progress_updated_at = ?7 WHERE id = ?1 AND status = 'running'");
  s.bind(1, id)
      .bind(2, p.fraction)
      .bind(3, p.time)
      .bind(4, p.duration)
      .bind(5, p.steps)
      .bind(6, p.eta_s)
      .bind(7, p.updated_at)
      .run();
}

bool JobStore::finish(const std::string& id, const RunRecord& r) {
  if (!is_final(r.status))
    throw std::invalid_argument(std::string("finish() of job ") + id + " with status " +
                                to_string(r.status));
  std::lock_guard lock(mutex_);
  Transaction tx(db_);
  auto s = db_.prepare(
      "UPDATE jobs SET status = ?2, error = ?3, wall_time_s = ?4, finished_at = ?5, "
      "result_path = ?6, result_size = ?7, result_sha256 = ?8, progress_eta_s = 0, "
      "progress_updated_at = ?5, progress_fraction = CASE WHEN ?2 = 'succeeded' THEN 1.0 "
      "ELSE progress_fraction END, progress_steps = COALESCE(?9, progress_steps), "
      "progress_time = COALESCE(?10, progress_time) WHERE id = ?1 AND status = 'running'");
  auto opt = [](const std::string& v) {
    return v.empty() ? std::nullopt : std::optional<std::string>(v);
  };
  s.bind(1, id)
      .bind(2, std::string(to_string(r.status)))
      .bind(3, opt(r.error))
      .bind(4, r.wall_time_s)
      .bind(5, r.finished_at)
      .bind(6, opt(r.result.path))
      .bind(7, static_cast<std::int64_t>(r.result.size))
      .bind(8, opt(r.result.sha256));
  if (auto steps = metric(r.metrics, "steps"))
    s.bind(9, static_cast<std::int64_t>(*steps));
  else
    s.bind_null(9);
  s.bind(10, metric(r.metrics, "simulated_time"));
  s.run();
  if (s.changes() != 1) return false;
  if (!r.metrics.is_null()) {
    auto m = db_.prepare(
        "INSERT OR REPLACE INTO metrics (job_id, L, n_d, arrest_position, propagation_distance, "
        "arrival_time_at_probe, max_rupture_speed, mean_rupture_speed, max_slip_velocity, "
        "outcome, energy_error, wall_time_s, steps, dt, metrics_json, front_json) "
        "SELECT ?1, L, n_d, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14 "
        "FROM jobs WHERE id = ?1");
    const auto& x = r.metrics;
    auto outcome = x.contains("outcome") && x["outcome"].is_string()
                       ? std::optional<std::string>(x["outcome"].get<std::string>())
                       : std::nullopt;
    auto steps = metric(x, "steps");
    m.bind(1, id)
        .bind(2, metric(x, "arrest_position"))
        .bind(3, metric(x, "propagation_distance"))
        .bind(4, metric(x, "arrival_time_at_probe"))
        .bind(5, either(metric(x, "max_rupture_speed"), metric(x, "rupture_speed", "max")))
        .bind(6, either(metric(x, "mean_rupture_speed"), metric(x, "rupture_speed", "mean")))
        .bind(7, metric(x, "max_slip_velocity"))
        .bind(8, outcome)
        .bind(9, metric(x, "energy_error"))
        .bind(10, either(metric(x, "wall_time_s"), std::optional<double>(r.wall_time_s)));
    if (steps)
      m.bind(11, static_cast<std::int64_t>(*steps));
    else
      m.bind_null(11);
    m.bind(12, metric(x, "dt"))
        .bind(13, r.metrics.dump())
        .bind(14, r.front.is_null() ? std::nullopt : std::optional<std::string>(r.front.dump()))
        .run();
  }
  tx.commit();
  return true;
}

bool JobStore::cancel_queued(const std::string& id, const std::string& finished_at) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("UPDATE jobs SET status = 'cancelled', finished_at = ?2, "
                       "error = 'cancelled while queued' WHERE id = ?1 AND status = 'queued'");
  s.bind(1, id).bind(2, finished_at).run();
  return s.changes() == 1;
}

namespace {
const char* requeue_set = "UPDATE jobs SET status = 'queued', started_at = NULL, "
                          "progress_fraction = 0, progress_time = 0, progress_steps = 0, "
                          "progress_eta_s = NULL, progress_updated_at = NULL, "
                          "slurm_job_id = NULL, slurm_state = NULL ";
}

bool JobStore::requeue(const std::string& id) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string(requeue_set) + "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).run();
  return s.changes() == 1;
}

int JobStore::requeue_all_running(bool keep_slurm_jobs) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string(requeue_set) + "WHERE status = 'running'" +
                       (keep_slurm_jobs ? " AND slurm_job_id IS NULL" : ""));
  s.run();
  return s.changes();
}

std::vector<Job> JobStore::queued_jobs() {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string("SELECT ") + job_columns + job_from +
                       "WHERE j.status = 'queued' ORDER BY j.priority DESC, j.seq ASC");
  std::vector<Job> jobs;
  while (s.step())
    jobs.push_back(read_job(s));
  return jobs;
}

JobPage JobStore::list(const JobFilter& f) {
  std::string where = "WHERE 1 = 1";
  SqlParams params;
  if (!f.statuses.empty()) {
    where += " AND j.status IN (";
    for (std::size_t i = 0; i < f.statuses.size(); ++i)
      where += (i ? ", " : "") + params.add(to_string(f.statuses[i]));
    where += ")";
  }
  if (!f.tag.empty())
    where += " AND EXISTS (SELECT 1 FROM json_each(j.tags) WHERE json_each.value = " +
             params.add(f.tag) + ")";
  auto equal = [&](const char* column, const std::string& value) {
    if (!value.empty()) where += std::string(" AND ") + column + " = " + params.add(value);
  };
  equal("j.name", f.name);
  equal("m.outcome", f.outcome);
  equal("j.submitted_by", f.submitted_by);
  equal("j.spec_sha256", f.spec_sha256);
  equal("j.scene_hash", f.scene_hash);
  equal("j.study_id", f.study_id);
  auto range = [&](const char* column, const char* op, const std::optional<double>& v) {
    if (v) where += std::string(" AND ") + column + " " + op + " " + params.add(*v);
  };
  range("j.L", ">=", f.L_min);
  range("j.L", "<=", f.L_max);
  range("j.n_d", ">=", f.n_d_min);
  range("j.n_d", "<=", f.n_d_max);
  for (const auto& c : f.conditions)
    where += " AND " + condition_sql(c, params);
  std::string order = " ORDER BY ";
  if (f.sort.empty()) {
    if (f.before_seq) where += " AND j.seq < " + params.add(static_cast<double>(*f.before_seq));
  } else {
    for (const auto& key : f.sort)
      order += sort_sql(key, params) + ", ";
  }
  order += "j.seq DESC";
  int limit = std::max(1, f.limit);
  std::string tail = " LIMIT " + std::to_string(limit + 1);
  if (!f.sort.empty() && f.offset > 0) tail += " OFFSET " + std::to_string(f.offset);
  std::lock_guard lock(mutex_);
  auto s = db_.prepare(std::string("SELECT ") + job_columns + job_from + where + order + tail);
  for (std::size_t i = 0; i < params.values.size(); ++i)
    std::visit([&](const auto& v) { s.bind(static_cast<int>(i + 1), v); }, params.values[i]);
  JobPage page;
  while (s.step()) {
    if (static_cast<int>(page.jobs.size()) == limit) {
      if (f.sort.empty())
        page.next_cursor = page.jobs.back().seq;
      else
        page.next_offset = f.offset + limit;
      break;
    }
    page.jobs.push_back(read_job(s));
  }
  auto status = db_.prepare("SELECT convergence_status FROM study_runs WHERE job_id = ?1 "
                            "ORDER BY rowid DESC LIMIT 1");
  for (const auto& job : page.jobs) {
    status.reset();
    status.bind(1, job.id);
    if (status.step()) page.convergence_status[job.id] = status.text(0);
  }
  return page;
}

std::map<std::string, std::int64_t> JobStore::count_by_status() {
  std::lock_guard lock(mutex_);
  std::map<std::string, std::int64_t> counts;
  for (JobStatus st : {JobStatus::queued, JobStatus::running, JobStatus::succeeded,
                       JobStatus::failed, JobStatus::cancelled})
    counts[to_string(st)] = 0;
  auto s = db_.prepare("SELECT status, COUNT(*) FROM jobs GROUP BY status");
  while (s.step())
    counts[s.text(0)] = s.integer(1);
  return counts;
}

std::optional<nlohmann::json> JobStore::front(const std::string& id) {
  std::lock_guard lock(mutex_);
  auto s = db_.prepare("SELECT front_json FROM metrics WHERE job_id = ?1");
  s.bind(1, id);
  if (!s.step()) return std::nullopt;
  return parse_stored_json(s.text(0), "front of job " + id);
}

} // namespace slipfront::server
