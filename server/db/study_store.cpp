#include "server/db/study_store.hpp"

#include "server/core/clock.hpp"
#include "server/db/file_intents.hpp"

#include <set>
#include <stdexcept>

namespace slipfront::server {

using nlohmann::json;

namespace {

const char* study_columns =
    "seq, id, name, tags, kind, base_spec, request, scene_hash, submitted_by, priority, fresh, "
    "created_at, updated_at, finished_at, status, runs_done, runs_total, L_c, "
    "spectral_critical_length, result, idempotency_key, note, archived_at FROM studies ";

// A row of SELECT study_columns, read by column name.
StudyRecord read_study(const Statement& s) {
  StudyRecord r;
  r.seq = s.integer("seq");
  r.id = s.text("id");
  r.name = s.text("name");
  r.tags =
      parse_stored_json(s.text("tags"), "tags of study " + r.id).get<std::vector<std::string>>();
  r.kind = s.text("kind");
  r.base = parse_stored_json(s.text("base_spec"), "base of study " + r.id);
  r.request = parse_stored_json(s.text("request"), "request of study " + r.id);
  r.scene_hash = s.text("scene_hash");
  r.submitted_by = s.text("submitted_by");
  r.priority = static_cast<int>(s.integer("priority"));
  r.fresh = s.integer("fresh") != 0;
  r.created_at = s.text("created_at");
  r.updated_at = s.text("updated_at");
  r.finished_at = s.text("finished_at");
  const auto status = api::parse_study_status(s.text("status"));
  if (!status)
    throw std::runtime_error("study " + r.id + " has unknown status " + s.text("status"));
  r.status = *status;
  r.runs_done = static_cast<int>(s.integer("runs_done"));
  r.runs_total = static_cast<int>(s.integer("runs_total"));
  r.L_c = s.real("L_c");
  r.spectral_critical_length = s.real("spectral_critical_length");
  r.result = parse_stored_json(s.text("result"), "result of study " + r.id);
  r.idempotency_key = s.text("idempotency_key");
  r.note = s.text("note");
  r.archived_at = s.text("archived_at");
  return r;
}

// Columns 0..8 of study_runs, then the job's.
const char* run_columns =
    "r.job_id, r.regime, r.L, r.n_d, r.convergence_status, r.partner_n_d, "
    "r.propagation_distance_change, r.arrival_time_change, r.reason, j.status, m.metrics_json, "
    "j.wall_time_s, j.memory_estimate_bytes, j.scene_hash, j.cached_from, j.result_path, "
    "j.submitted_by, j.study_id, j.error ";

StudyRunRow read_run(const Statement& s) {
  StudyRunRow r;
  r.job_id = s.text(0);
  r.regime = s.text(1);
  r.L = s.real(2);
  r.n_d = s.real(3);
  r.convergence_status = s.text(4);
  r.partner_n_d = s.real(5);
  r.propagation_distance_change = s.real(6);
  r.arrival_time_change = s.real(7);
  r.reason = s.text(8);
  r.job_status = s.text(9);
  r.metrics = parse_stored_json(s.text(10), "metrics of job " + r.job_id);
  r.wall_time_s = s.is_null(11) ? 0.0 : s.real(11);
  r.memory_estimate_bytes = s.is_null(12) ? 0.0 : s.real(12);
  r.scene_hash = s.text(13);
  r.cached_from = s.text(14);
  r.result_path = s.text(15);
  r.submitted_by = s.text(16);
  r.study_id = s.text(17);
  r.error = s.text(18);
  return r;
}

std::optional<std::string> text_or_null(const std::string& v) {
  return v.empty() ? std::nullopt : std::optional<std::string>(v);
}

} // namespace

void StudyStore::insert(const StudyRecord& st) {
  db_.with_db([&](Database& db) {
    auto s = db.prepare("INSERT INTO studies (id, name, tags, kind, base_spec, request, "
                        "scene_hash, submitted_by, priority, fresh, created_at, updated_at, "
                        "status, idempotency_key) "
                        "VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?11, ?12, ?13)");
    s.bind(1, st.id)
        .bind(2, st.name)
        .bind(3, json(st.tags).dump())
        .bind(4, st.kind)
        .bind(5, st.base.dump())
        .bind(6, st.request.dump())
        .bind(7, st.scene_hash)
        .bind(8, st.submitted_by)
        .bind(9, std::int64_t{st.priority})
        .bind(10, std::int64_t{st.fresh ? 1 : 0})
        .bind(11, st.created_at)
        .bind(12, std::string(api::to_string(st.status)))
        .bind(13, text_or_null(st.idempotency_key))
        .run();
  });
}

void StudyStore::add_run(const std::string& study_id, const std::string& job_id,
                         const std::string& regime, double L, double n_d) {
  db_.with_db([&](Database& db) {
    auto s = db.prepare("INSERT OR IGNORE INTO study_runs (study_id, job_id, regime, L, n_d) "
                        "VALUES (?1, ?2, ?3, ?4, ?5)");
    s.bind(1, study_id).bind(2, job_id).bind(3, regime).bind(4, L).bind(5, n_d).run();
  });
}

std::optional<StudyRecord> StudyStore::find_by_idempotency_key(const std::string& user,
                                                               const std::string& key) {
  return db_.with_db([&](Database& db) -> std::optional<StudyRecord> {
    auto s = db.prepare(std::string("SELECT ") + study_columns +
                        "WHERE submitted_by = ?1 AND idempotency_key = ?2");
    s.bind(1, user).bind(2, key);
    if (!s.step()) return std::nullopt;
    return read_study(s);
  });
}

std::optional<StudyRecord> StudyStore::get(const std::string& id) {
  return db_.with_db([&](Database& db) -> std::optional<StudyRecord> {
    auto s = db.prepare(std::string("SELECT ") + study_columns + "WHERE id = ?1");
    s.bind(1, id);
    if (!s.step()) return std::nullopt;
    return read_study(s);
  });
}

std::vector<StudyRecord> StudyStore::list(int limit, std::optional<std::int64_t> before_seq,
                                          std::optional<api::StudyStatus> status,
                                          ArchivedRuns archived) {
  return db_.with_db([&](Database& db) {
    std::string sql = std::string("SELECT ") + study_columns + "WHERE 1 = 1";
    if (before_seq) sql += " AND seq < ?1";
    if (status) sql += " AND status = ?2";
    if (archived == ArchivedRuns::exclude) sql += " AND archived_at IS NULL";
    if (archived == ArchivedRuns::only) sql += " AND archived_at IS NOT NULL";
    sql += " ORDER BY seq DESC LIMIT " + std::to_string(limit);
    auto s = db.prepare(sql);
    if (before_seq) s.bind(1, *before_seq);
    if (status) s.bind(2, std::string(api::to_string(*status)));
    std::vector<StudyRecord> out;
    while (s.step())
      out.push_back(read_study(s));
    return out;
  });
}

std::vector<std::string> StudyStore::running_ids() {
  return db_.with_db([&](Database& db) {
    auto s = db.prepare("SELECT id FROM studies WHERE status = 'running' ORDER BY seq");
    std::vector<std::string> out;
    while (s.step())
      out.push_back(s.text(0));
    return out;
  });
}

void StudyStore::set_status(const std::string& id, api::StudyStatus status, const std::string& at) {
  db_.with_db([&](Database& db) {
    db.prepare("UPDATE studies SET status = ?2, updated_at = ?3 WHERE id = ?1")
        .bind(1, id)
        .bind(2, std::string(api::to_string(status)))
        .bind(3, at)
        .run();
  });
}

std::vector<std::string> StudyStore::unsettled_cancelled_ids() {
  return db_.with_db([&](Database& db) {
    auto s = db.prepare(
        "SELECT s.id FROM studies s WHERE s.status = 'cancelled' AND (s.runs_done < s.runs_total "
        "OR EXISTS (SELECT 1 FROM study_runs r JOIN jobs j ON j.id = r.job_id "
        "WHERE r.study_id = s.id AND j.status IN ('queued', 'running'))) ORDER BY s.seq");
    std::vector<std::string> out;
    while (s.step())
      out.push_back(s.text(0));
    return out;
  });
}

std::vector<StudyRunRow> StudyStore::runs(const std::string& study_id) {
  return db_.with_db([&](Database& db) {
    auto s = db.prepare(std::string("SELECT ") + run_columns +
                        "FROM study_runs r JOIN jobs j ON j.id = r.job_id "
                        "LEFT JOIN metrics m ON m.job_id = j.id WHERE r.study_id = ?1 "
                        "ORDER BY r.regime, r.L, r.n_d, j.seq");
    s.bind(1, study_id);
    std::vector<StudyRunRow> out;
    while (s.step())
      out.push_back(read_run(s));
    return out;
  });
}

std::vector<StudyRunRow> StudyStore::scene_runs(const std::string& scene_hash) {
  return db_.with_db([&](Database& db) {
    auto s = db.prepare(
        "SELECT j.id, '', j.L, j.n_d, 'pending', NULL, NULL, NULL, NULL, j.status, "
        "m.metrics_json, j.wall_time_s, j.memory_estimate_bytes, j.scene_hash, j.cached_from, "
        "j.result_path, j.submitted_by, j.study_id, j.error FROM jobs j "
        "LEFT JOIN metrics m ON m.job_id = j.id WHERE j.scene_hash = ?1 "
        "AND j.status IN ('succeeded', 'failed') AND j.cached_from IS NULL "
        "ORDER BY j.L, j.n_d, j.seq");
    s.bind(1, scene_hash);
    std::vector<StudyRunRow> out;
    while (s.step())
      out.push_back(read_run(s));
    return out;
  });
}

std::string StudyStore::study_of_job(const std::string& job_id) {
  return db_.with_db([&](Database& db) {
    auto s = db.prepare("SELECT study_id FROM jobs WHERE id = ?1");
    s.bind(1, job_id);
    return s.step() ? s.text(0) : std::string();
  });
}

bool study_exists(Database& db, const std::string& id) {
  auto s = db.prepare("SELECT 1 FROM studies WHERE id = ?1");
  s.bind(1, id);
  return s.step();
}

void insert_imported_study(Database& db, const StudyRecord& st,
                           const std::vector<StudyRunRow>& runs) {
  db.prepare("INSERT INTO studies (id, name, tags, kind, base_spec, request, scene_hash, "
             "submitted_by, priority, fresh, created_at, updated_at, finished_at, status, "
             "runs_done, runs_total, L_c, spectral_critical_length, result, note) VALUES (?1, "
             "?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11, ?12, ?13, ?14, ?15, ?16, ?17, ?18, "
             "?19, ?20)")
      .bind(1, st.id)
      .bind(2, st.name)
      .bind(3, json(st.tags).dump())
      .bind(4, st.kind)
      .bind(5, st.base.dump())
      .bind(6, st.request.dump())
      .bind(7, st.scene_hash)
      .bind(8, st.submitted_by)
      .bind(9, std::int64_t{st.priority})
      .bind(10, std::int64_t{st.fresh ? 1 : 0})
      .bind(11, st.created_at)
      .bind(12, text_or_null(st.updated_at))
      .bind(13, text_or_null(st.finished_at))
      .bind(14, std::string(api::to_string(st.status)))
      .bind(15, std::int64_t{st.runs_done})
      .bind(16, std::int64_t{st.runs_total})
      .bind(17, st.L_c)
      .bind(18, st.spectral_critical_length)
      .bind(19, st.result.dump(-1, ' ', false, json::error_handler_t::replace))
      .bind(20, st.note)
      .run();
  auto s = db.prepare("INSERT OR IGNORE INTO study_runs (study_id, job_id, regime, L, n_d, "
                      "convergence_status, partner_n_d, propagation_distance_change, "
                      "arrival_time_change, reason) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, "
                      "?10)");
  for (const auto& r : runs) {
    s.bind(1, st.id)
        .bind(2, r.job_id)
        .bind(3, r.regime)
        .bind(4, r.L)
        .bind(5, r.n_d)
        .bind(6, r.convergence_status)
        .bind(7, r.partner_n_d)
        .bind(8, r.propagation_distance_change)
        .bind(9, r.arrival_time_change)
        .bind(10, r.reason)
        .run();
    s.reset();
  }
}

std::optional<api::TagsAfter> StudyStore::annotate(const std::string& id,
                                                   const api::TagChange& tags,
                                                   const std::optional<std::string>& note) {
  auto db = db_.lock();
  Transaction tx(*db);
  auto row = db->prepare("SELECT tags FROM studies WHERE id = ?1");
  row.bind(1, id);
  if (!row.step()) return std::nullopt;
  const auto stored =
      parse_stored_json(row.text(0), "tags of study " + id).get<std::vector<std::string>>();
  api::TagsAfter after = api::apply_tag_change(stored, tags);
  if (after.error) return after;
  db->prepare("UPDATE studies SET tags = ?2, note = COALESCE(?3, note) WHERE id = ?1")
      .bind(1, id)
      .bind(2, json(after.tags).dump())
      .bind(3, note)
      .run();
  tx.commit();
  return after;
}

bool StudyStore::set_archived(const std::string& id, const std::string& archived_at) {
  auto db = db_.lock();
  auto s = db->prepare("UPDATE studies SET archived_at = ?2 WHERE id = ?1");
  s.bind(1, id).bind(2, text_or_null(archived_at)).run();
  return s.changes() == 1;
}

StudyStore::Removal StudyStore::remove(const std::string& id) {
  using Kind = Removal::Kind;
  auto db = db_.lock();
  Transaction tx(*db);
  auto study = db->prepare("SELECT status FROM studies WHERE id = ?1");
  study.bind(1, id);
  if (!study.step()) return {};
  if (study.text(0) == "running") return {Kind::running, {}, {}, 0};
  // Its runs: those it submitted (or an import stored for it), but not one another study also
  // lists. A run it only lists (one already here when it was imported) stays, unlisted.
  auto runs = db->prepare(
      "SELECT j.id, j.status, j.result_path FROM jobs j WHERE j.study_id = ?1 AND NOT EXISTS "
      "(SELECT 1 FROM study_runs o WHERE o.job_id = j.id AND o.study_id != ?1)");
  runs.bind(1, id);
  Removal removal{Kind::removed, {}, {}, 0};
  std::set<std::string> paths;
  while (runs.step()) {
    const auto status = parse_status(runs.text(1));
    if (!status || !is_final(*status)) return {Kind::runs_not_final, {}, {}, 0};
    removal.job_ids.push_back(runs.text(0));
    if (!runs.text(2).empty()) paths.insert(runs.text(2));
  }
  db->prepare("DELETE FROM study_runs WHERE study_id = ?1").bind(1, id).run();
  auto metrics = db->prepare("DELETE FROM metrics WHERE job_id = ?1");
  auto jobs = db->prepare("DELETE FROM jobs WHERE id = ?1");
  for (const auto& job : removal.job_ids) {
    metrics.bind(1, job).run();
    metrics.reset();
    jobs.bind(1, job).run();
    jobs.reset();
  }
  db->prepare("DELETE FROM studies WHERE id = ?1").bind(1, id).run();
  // A cache hit elsewhere shares the file of the run it reused: the file goes with the last.
  auto users = db->prepare("SELECT count(*) FROM jobs WHERE result_path = ?1");
  for (const auto& path : paths) {
    users.bind(1, path);
    if (users.step() && users.integer(0) == 0) removal.orphaned_results.push_back(path);
    users.reset();
  }
  if (!removal.orphaned_results.empty())
    removal.intent = insert_file_intent(*db, "delete", removal.orphaned_results, now_iso8601());
  tx.commit();
  return removal;
}

void StudyStore::save_analysis(const StudyRecord& st, const std::vector<StudyRunRow>& runs) {
  db_.with_db([&](Database& db) {
    Transaction tx(db);
    auto r = db.prepare("UPDATE study_runs SET convergence_status = ?3, partner_n_d = ?4, "
                        "propagation_distance_change = ?5, arrival_time_change = ?6, "
                        "reason = ?7 WHERE study_id = ?1 AND job_id = ?2");
    for (const auto& run : runs) {
      r.bind(1, st.id)
          .bind(2, run.job_id)
          .bind(3, run.convergence_status)
          .bind(4, run.partner_n_d)
          .bind(5, run.propagation_distance_change)
          .bind(6, run.arrival_time_change)
          .bind(7, run.reason)
          .run();
      r.reset();
    }
    auto s = db.prepare("UPDATE studies SET status = ?2, runs_done = ?3, runs_total = ?4, "
                        "L_c = ?5, spectral_critical_length = ?6, result = ?7, updated_at = ?8, "
                        "finished_at = ?9 WHERE id = ?1");
    s.bind(1, st.id)
        .bind(2, std::string(api::to_string(st.status)))
        .bind(3, std::int64_t{st.runs_done})
        .bind(4, std::int64_t{st.runs_total})
        .bind(5, st.L_c)
        .bind(6, st.spectral_critical_length)
        .bind(7, st.result.dump(-1, ' ', false, json::error_handler_t::replace))
        .bind(8, st.updated_at)
        .bind(9, text_or_null(st.finished_at))
        .run();
    tx.commit();
  });
}

} // namespace slipfront::server
