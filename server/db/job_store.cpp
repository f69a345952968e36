#include "server/db/job_store.hpp"

#include "api/job_spec.hpp"
#include "api/metrics_row.hpp"
#include "server/core/log.hpp"
#include "server/db/job_rows.hpp"

#include <cmath>
#include <stdexcept>

namespace slipfront::server {

std::int64_t JobStore::insert(const Job& job) {
  auto db = db_.lock();
  Transaction tx(*db);
  auto s = db->prepare(insert_job_sql());
  bind_new_job(s, job);
  s.run();
  auto seq = db->last_insert_rowid();
  if (!job.cached_from.empty()) {
    auto copy = db->prepare("INSERT INTO metrics (job_id, " + metrics_columns() + ") SELECT ?1, " +
                            metrics_columns() + " FROM metrics WHERE job_id = ?2");
    copy.bind(1, job.id).bind(2, job.cached_from).run();
  }
  tx.commit();
  return seq;
}

std::optional<Job> JobStore::query_one(const std::string& where,
                                       const std::vector<std::string>& args) {
  auto db = db_.lock();
  auto s = db->prepare(select_jobs() + where);
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
                                           const nlohmann::json& output,
                                           const CacheRequester& requester) {
  // Both sides of the output comparison are nlohmann dumps (keys sorted, shortest round-trip
  // numbers) and SQLite's json() keeps number tokens as written, so equal text is equal
  // settings. A spec without `output` compares as null.
  return query_one("WHERE j.spec_sha256 = ?1 AND j.code_version = ?2 AND j.status = 'succeeded' "
                   "AND j.result_path IS NOT NULL AND m.job_id IS NOT NULL "
                   "AND ifnull(json_extract(j.spec, '$.output'), 'null') = json(?3) "
                   "AND (j.result_imported_by IS NULL OR (?5 = '1' AND j.result_imported_by = ?4)) "
                   "ORDER BY j.seq DESC LIMIT 1",
                   {spec_sha256, code_version, output.dump(), requester.user,
                    requester.authenticated ? "1" : "0"});
}

bool JobStore::mark_running(const std::string& id, const std::string& started_at,
                            const std::string& host, const std::string& code_version,
                            const std::string& executor) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET status = 'running', started_at = ?2, host = ?3, "
                       "code_version = ?4, attempts = attempts + 1, progress_updated_at = ?2, "
                       "executor = ?5, slurm_job_id = NULL, slurm_state = NULL "
                       "WHERE id = ?1 AND status = 'queued'");
  s.bind(1, id).bind(2, started_at).bind(3, host).bind(4, code_version).bind(5, executor).run();
  return s.changes() == 1;
}

bool JobStore::set_slurm_job(const std::string& id, const std::string& slurm_job_id,
                             const std::string& slurm_state) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET slurm_job_id = ?2, slurm_state = ?3 "
                       "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).bind(2, slurm_job_id).bind(3, slurm_state).run();
  return s.changes() == 1;
}

void JobStore::update_slurm_state(const std::string& id, const std::string& slurm_state,
                                  const std::string& host) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET slurm_state = ?2, host = COALESCE(?3, host) "
                       "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).bind(2, slurm_state);
  if (host.empty())
    s.bind_null(3);
  else
    s.bind(3, host);
  s.run();
}

std::vector<Job> JobStore::running_slurm_jobs() {
  auto db = db_.lock();
  auto s = db->prepare(select_jobs() + "WHERE j.status = 'running' AND j.slurm_job_id IS NOT NULL "
                                       "ORDER BY j.seq ASC");
  std::vector<Job> jobs;
  std::vector<std::string> skipped;
  while (s.step())
    if (auto job = read_job_or_skip(s, skipped)) jobs.push_back(std::move(*job));
  for (const auto& why : skipped)
    log_error("job " + why + "; left out (slipfront check lists such rows)");
  return jobs;
}

void JobStore::update_progress(const std::string& id, const JobProgress& p) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET progress_fraction = ?2, progress_time = ?3, "
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

void JobStore::write_metrics(Database& db, const std::string& id, const RunRecord& r) {
  const api::MetricsRow row = api::metrics_row(r.metrics); // the one place it is derived
  auto m =
      db.prepare("INSERT OR REPLACE INTO metrics (job_id, " + metrics_columns() +
                 ") SELECT ?1, L, n_d, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14 "
                 "FROM jobs WHERE id = ?1");
  m.bind(1, id)
      .bind(2, row.arrest_position)
      .bind(3, row.propagation_distance)
      .bind(4, row.arrival_time_at_probe)
      .bind(5, row.max_rupture_speed)
      .bind(6, row.mean_rupture_speed)
      .bind(7, row.max_slip_velocity)
      .bind(8, row.outcome)
      .bind(9, row.energy_error)
      .bind(10, row.wall_time_s.value_or(r.wall_time_s));
  if (row.steps)
    m.bind(11, *row.steps);
  else
    m.bind_null(11);
  m.bind(12, row.dt)
      .bind(13, r.metrics.dump())
      .bind(14, r.front.is_null() ? std::nullopt : std::optional<std::string>(r.front.dump()))
      .run();
}

bool JobStore::finish(const std::string& id, const RunRecord& r) {
  if (!is_final(r.status))
    throw std::invalid_argument(std::string("finish() of job ") + id + " with status " +
                                to_string(r.status));
  auto db = db_.lock();
  Transaction tx(*db);
  auto s = db->prepare(
      "UPDATE jobs SET status = ?2, error = ?3, wall_time_s = ?4, finished_at = ?5, "
      "result_path = ?6, result_size = ?7, result_sha256 = ?8, progress_eta_s = 0, "
      "progress_updated_at = ?5, progress_fraction = CASE WHEN ?2 = 'succeeded' THEN 1.0 "
      "ELSE progress_fraction END, progress_steps = COALESCE(?9, progress_steps), "
      "progress_time = COALESCE(?10, progress_time) WHERE id = ?1 AND status = 'running'");
  const api::MetricsRow row = api::metrics_row(r.metrics); // the one place it is derived
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
  if (row.steps)
    s.bind(9, *row.steps);
  else
    s.bind_null(9);
  s.bind(10, row.simulated_time);
  s.run();
  if (s.changes() != 1) return false;
  if (!r.metrics.is_null()) write_metrics(*db, id, r);
  tx.commit();
  return true;
}

bool JobStore::cancel_queued(const std::string& id, const std::string& finished_at) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE jobs SET status = 'cancelled', finished_at = ?2, "
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
  auto db = db_.lock();
  auto s = db->prepare(std::string(requeue_set) + "WHERE id = ?1 AND status = 'running'");
  s.bind(1, id).run();
  return s.changes() == 1;
}

int JobStore::requeue_all_running(bool keep_slurm_jobs) {
  auto db = db_.lock();
  auto s = db->prepare(std::string(requeue_set) + "WHERE status = 'running'" +
                       (keep_slurm_jobs ? " AND slurm_job_id IS NULL" : ""));
  s.run();
  return s.changes();
}

std::vector<Job> JobStore::queued_jobs() {
  auto db = db_.lock();
  auto s =
      db->prepare(select_jobs() + "WHERE j.status = 'queued' ORDER BY j.priority DESC, j.seq ASC");
  std::vector<Job> jobs;
  std::vector<std::string> skipped;
  while (s.step())
    if (auto job = read_job_or_skip(s, skipped)) jobs.push_back(std::move(*job));
  for (const auto& why : skipped)
    log_error("job " + why + "; left out (slipfront check lists such rows)");
  return jobs;
}

JobPage JobStore::scan(const JobFilter& f, const EachJob& each) {
  const ListQuery q = list_query(f);
  const int limit = std::max(1, f.limit);
  return db_.read([&](Database& db) {
    auto s = db.prepare(q.sql);
    bind_all(s, q.params);
    auto status = db.prepare("SELECT convergence_status FROM study_runs WHERE job_id = ?1 "
                             "ORDER BY rowid DESC LIMIT 1");
    JobPage page;
    int rows = 0;              // read or skipped: the offset of a sorted listing counts both
    std::int64_t last_seq = 0; // of the last row, read or skipped
    while (s.step()) {
      if (rows == limit) {
        if (f.sort.empty())
          page.next_cursor = last_seq;
        else
          page.next_offset = f.offset + limit;
        break;
      }
      ++rows;
      last_seq = s.integer("seq");
      auto job = read_job_or_skip(s, page.skipped);
      if (!job) continue;
      status.reset();
      status.bind(1, job->id);
      each(std::move(*job), status.step() ? status.text(0) : std::string());
    }
    return page;
  });
}

JobPage JobStore::list(const JobFilter& f) {
  std::vector<Job> jobs;
  std::map<std::string, std::string> statuses;
  JobPage page = scan(f, [&](Job&& job, const std::string& convergence_status) {
    if (!convergence_status.empty()) statuses[job.id] = convergence_status;
    jobs.push_back(std::move(job));
  });
  page.jobs = std::move(jobs);
  page.convergence_status = std::move(statuses);
  return page;
}

std::map<std::string, std::int64_t> JobStore::count_by_status() {
  auto db = db_.lock();
  std::map<std::string, std::int64_t> counts;
  for (JobStatus st : {JobStatus::queued, JobStatus::running, JobStatus::succeeded,
                       JobStatus::failed, JobStatus::cancelled})
    counts[to_string(st)] = 0;
  auto s = db->prepare("SELECT status, COUNT(*) FROM jobs GROUP BY status");
  while (s.step())
    counts[s.text(0)] = s.integer(1);
  return counts;
}

std::vector<MalformedRow> JobStore::malformed_rows() {
  return db_.with_db([](Database& db) { return find_malformed_rows(db); });
}

std::optional<nlohmann::json> JobStore::front(const std::string& id) {
  auto db = db_.lock();
  auto s = db->prepare("SELECT front_json FROM metrics WHERE job_id = ?1");
  s.bind(1, id);
  if (!s.step()) return std::nullopt;
  return parse_stored_json(s.text(0), "front of job " + id);
}

} // namespace slipfront::server
