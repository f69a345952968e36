// The studies and study_runs tables (migration 2 -> 3, server/db/migrations/m3_studies.cpp),
// in the jobs database, on its shared connection (server/db/store_db.hpp). Convergence statuses,
// L_c and the analysis JSON are stored when a run of the study finishes (StudySupervisor), so
// reading a study is a few indexed SELECTs.
#pragma once

#include "server/core/study.hpp"
#include "server/db/job_store.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

// For an import, on the caller's connection (inside its transaction): whether a study has the
// id, and the study stored as its archive gave it, listing its runs by `runs[i].job_id`.
bool study_exists(Database& db, const std::string& id);
void insert_imported_study(Database& db, const StudyRecord& study,
                           const std::vector<StudyRunRow>& runs);

class StudyStore {
public:
  explicit StudyStore(JobStore& jobs) : db_(jobs.db()) {}

  void insert(const StudyRecord& study);
  void add_run(const std::string& study_id, const std::string& job_id, const std::string& regime,
               double L, double n_d);
  std::optional<StudyRecord> get(const std::string& id);
  // The study `user` created with this Idempotency-Key, if any.
  std::optional<StudyRecord> find_by_idempotency_key(const std::string& user,
                                                     const std::string& key);
  // Newest first; `before_seq` is the cursor of the previous page.
  std::vector<StudyRecord> list(int limit, std::optional<std::int64_t> before_seq,
                                std::optional<api::StudyStatus> status,
                                ArchivedRuns archived = ArchivedRuns::include);
  std::vector<std::string> running_ids();
  // Cancelled studies with a run not final, or whose stored progress is behind.
  std::vector<std::string> unsettled_cancelled_ids();
  std::vector<StudyRunRow> runs(const std::string& study_id);
  // Every succeeded or failed job of a scene, whoever submitted it; reused (cached) copies
  // are left out, their original is there.
  std::vector<StudyRunRow> scene_runs(const std::string& scene_hash);
  std::string study_of_job(const std::string& job_id); // "" = none

  // Sets the study's status and updated_at (cancellation; finished_at follows when the
  // last run ends, analyse_study).
  void set_status(const std::string& id, api::StudyStatus status, const std::string& at);

  // What an owner keeps with a study (docs/server.md "Keep, annotate, share"): its tags
  // changed from those stored under the write lock, and its note; nullopt for an unknown
  // study, else what the change gave (an error: nothing changed).
  std::optional<api::TagsAfter> annotate(const std::string& id, const api::TagChange& tags,
                                         const std::optional<std::string>& note);
  // archived_at "" lists it again; false for an unknown study.
  bool set_archived(const std::string& id, const std::string& archived_at);
  struct Removal {
    enum class Kind { removed, not_found, running, runs_not_final } kind = Kind::not_found;
    std::vector<std::string> job_ids;          // removed: its runs, deleted with it
    std::vector<std::string> orphaned_results; // removed: the result files no row refers to now
    std::int64_t intent = 0;                   // with orphaned results: the intent to remove them
  };
  // Deletes a study that is over (finished or cancelled, every run final) with its runs and
  // their metrics, in one transaction that also records the intent to remove the result files
  // no other row refers to (forget it once they are gone; start-up removes them otherwise).
  // Its runs are those it submitted (jobs.study_id); a run another study also lists stays, and
  // so does a run it only lists (already here when the study was imported).
  Removal remove(const std::string& id);

  // Stores the statuses of `runs` (by job id) and the study's summary in one transaction.
  void save_analysis(const StudyRecord& study, const std::vector<StudyRunRow>& runs);

private:
  StoreDb& db_;
};

} // namespace slipfront::server
