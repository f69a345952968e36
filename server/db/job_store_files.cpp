// The JobStore calls that keep the result files and the rows in step (server/db/
// file_intents.hpp): the intents of imports and deletes, the paths the rows refer to, and
// the insertion of imported runs in one transaction.
#include "server/core/clock.hpp"
#include "server/db/job_rows.hpp"
#include "server/db/job_store.hpp"

namespace slipfront::server {

std::int64_t JobStore::record_file_intent(const std::string& kind,
                                          const std::vector<std::string>& paths) {
  auto db = db_.lock();
  Transaction tx(*db);
  const std::int64_t id = insert_file_intent(*db, kind, paths, now_iso8601());
  tx.commit();
  return id;
}

void JobStore::forget_file_intent(std::int64_t id) {
  auto db = db_.lock();
  delete_file_intent(*db, id);
}

std::vector<FileIntent> JobStore::file_intents() {
  auto db = db_.lock();
  return read_file_intents(*db);
}

ResultReferences JobStore::result_references() {
  return db_.read([](Database& db) { return read_result_references(db); });
}

std::vector<JobStore::ImportCandidate>
JobStore::import_candidates(const std::string& spec_sha256, const std::string& origin_id,
                            const std::string& result_sha256) {
  return db_.with_db([&](Database& db) {
    // instr(): a prefilter (the origin's id appears in the provenance's text); the caller
    // follows the provenance to its first server.
    auto s = db.prepare("SELECT id, status, imported_from, result_sha256 FROM jobs "
                        "WHERE spec_sha256 = ?1 AND status IN ('succeeded', 'failed', "
                        "'cancelled') AND (id = ?2 OR instr(imported_from, ?2) > 0 OR "
                        "(?3 != '' AND status = 'succeeded' AND result_sha256 = ?3)) "
                        "ORDER BY seq");
    s.bind(1, spec_sha256).bind(2, origin_id).bind(3, result_sha256);
    std::vector<ImportCandidate> out;
    while (s.step()) {
      ImportCandidate c;
      c.id = s.text(0);
      c.status = parse_status(s.text(1)).value_or(JobStatus::failed);
      c.imported_from = s.is_null(2) ? nlohmann::json()
                                     : parse_stored_json(s.text(2), "provenance of job " + c.id);
      c.result_sha256 = s.text(3);
      out.push_back(std::move(c));
    }
    return out;
  });
}

bool JobStore::insert_finished(const std::vector<FinishedRun>& runs, std::int64_t intent,
                               const std::function<void(Database&)>& also) {
  auto db = db_.lock();
  Transaction tx(*db);
  auto taken = db->prepare("SELECT 1 FROM jobs WHERE id = ?1");
  auto insert = db->prepare(insert_job_sql());
  for (const FinishedRun& run : runs) {
    taken.reset();
    taken.bind(1, run.job.id);
    if (taken.step()) return false; // rolled back: nothing of the import stays
    insert.reset();
    bind_new_job(insert, run.job);
    insert.run();
    if (!run.record.metrics.is_null()) write_metrics(*db, run.job.id, run.record);
  }
  if (also) also(*db);
  if (intent != 0) delete_file_intent(*db, intent);
  tx.commit();
  return true;
}

} // namespace slipfront::server
