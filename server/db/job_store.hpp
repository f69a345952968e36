// The jobs and metrics tables of the jobs database (server/db/: the connection, the
// migrations, the column lists). Every call is one short transaction on the shared
// connection, so HTTP handlers and workers can share it. Every state change is a conditional UPDATE
// (`WHERE status = ...`) so the transitions of job.hpp hold even when a cancel races a worker.
#pragma once

#include "api/run_annotations.hpp"
#include "server/core/job.hpp"
#include "server/core/job_filter.hpp"
#include "server/core/run_record.hpp"
#include "server/db/database.hpp"
#include "server/db/file_intents.hpp"
#include "server/db/malformed_rows.hpp"
#include "server/db/migrations.hpp"
#include "server/db/run_query_sql.hpp"
#include "server/db/store_db.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::server {

// Who asks for a cached result (JobStore::find_reusable): an imported result is offered to its
// importer only, and only when users are told apart by tokens (without them anyone may be
// anyone).
struct CacheRequester {
  std::string user;
  bool authenticated = false;
};

class JobStore {
public:
  static constexpr int schema_version = 13;

  // Opens the database (StoreDb: refuses an empty or, unless `integrity_check` is false, a
  // damaged file; brings the schema up to date).
  explicit JobStore(const std::string& path, bool integrity_check = true)
      : db_(path, integrity_check) {}

  // Inserts a new job (status queued, or succeeded with cached_from set: then the metrics
  // and front of cached_from are copied in the same transaction). Returns its seq.
  std::int64_t insert(const Job& job);

  std::optional<Job> get(const std::string& id);
  std::optional<Job> find_by_idempotency_key(const std::string& user, const std::string& key);
  // The newest succeeded job with this physics hash and code version that has a result
  // written with these output settings (the spec's `output`, which the hash leaves out: a
  // result file is reused only when it holds the sampling the new job asks for), computed
  // here or imported by `requester`.
  std::optional<Job> find_reusable(const std::string& spec_sha256, const std::string& code_version,
                                   const nlohmann::json& output,
                                   const CacheRequester& requester = {});

  // queued -> running (attempts + 1) on `executor` ("local" or "slurm"). False if the job
  // is no longer queued.
  bool mark_running(const std::string& id, const std::string& started_at, const std::string& host,
                    const std::string& code_version, const std::string& executor = "local");
  // The SLURM job of a running job (stored as soon as sbatch answers) and its last seen
  // SLURM state ("PENDING (Resources)", "RUNNING"); `host` "" keeps the stored host.
  bool set_slurm_job(const std::string& id, const std::string& slurm_job_id,
                     const std::string& slurm_state);
  void update_slurm_state(const std::string& id, const std::string& slurm_state,
                          const std::string& host);
  // Running jobs that have a SLURM job: what the SLURM executor re-attaches to at start-up.
  std::vector<Job> running_slurm_jobs();
  void update_progress(const std::string& id, const JobProgress& progress);
  // running -> final status, with the metrics row. False if the job was not running.
  bool finish(const std::string& id, const RunRecord& record);
  // queued -> cancelled. False if the job was not queued.
  bool cancel_queued(const std::string& id, const std::string& finished_at);
  // running -> queued: only for drain (SIGTERM) and crash recovery. False if not running.
  bool requeue(const std::string& id);
  // Crash recovery at start-up: every running job goes back to queued (with
  // `keep_slurm_jobs`, except those with a SLURM job: they are re-attached). Returns the count.
  int requeue_all_running(bool keep_slurm_jobs = false);
  // Queued jobs in run order: priority (high first), then submission order.
  std::vector<Job> queued_jobs();

  JobPage list(const JobFilter& filter);
  // The same jobs one at a time, none kept: each(job, its convergence status in its study,
  // "" if none). Returns the page without its jobs (the cursor, the skipped rows). For the
  // exports of up to 100000 rows (server/http/run_table.hpp).
  using EachJob = std::function<void(Job&& job, const std::string& convergence_status)>;
  JobPage scan(const JobFilter& filter, const EachJob& each);
  std::map<std::string, std::int64_t> count_by_status();
  // Rows whose stored JSON does not parse (slipfront check, the start-up log).
  std::vector<MalformedRow> malformed_rows();
  std::optional<nlohmann::json> front(const std::string& id); // null json if none stored
  // The finished runs an imported run may already be (JobService::already_here): of the spec
  // `spec_sha256`, and either the id `origin_id`, or an import whose provenance names it, or a
  // success with the result file `result_sha256` ("" = none). Few columns, indexed by spec.
  struct ImportCandidate {
    std::string id;
    JobStatus status = JobStatus::succeeded;
    nlohmann::json imported_from;
    std::string result_sha256;
  };
  std::vector<ImportCandidate> import_candidates(const std::string& spec_sha256,
                                                 const std::string& origin_id,
                                                 const std::string& result_sha256);

  // What an owner keeps with a run after submission (job_store_keep.cpp, docs/server.md
  // "Keep, annotate, share"). Each returns false for an unknown job.
  // The tags are changed from those stored, under the write lock: two changes at once both
  // hold. Returns nullopt for an unknown job, else what the change gave (an error: nothing
  // changed).
  std::optional<api::TagsAfter> annotate(const std::string& id, const api::TagChange& tags,
                                         const std::optional<std::string>& note);
  // archived_at "" restores the run (listed again).
  bool set_archived(const std::string& id, const std::string& archived_at);
  struct Removal {
    enum class Kind { removed, not_found, not_final, in_study } kind = Kind::not_found;
    std::string study_id;        // in_study: a study that holds the run
    std::string orphaned_result; // removed: its result path if no other job refers to it
    std::int64_t intent = 0;     // removed with an orphaned result: the intent to remove it
  };
  // Deletes a finished job and its metrics row in one transaction. A run of a study is not
  // deleted (the study keeps its runs); a queued or running one neither. When its result
  // file goes with it, the same transaction records the intent to remove the file
  // (forget_file_intent() once it is gone; start-up removes it otherwise).
  Removal remove(const std::string& id);

  // The result files and the rows in step (job_store_files.cpp, server/db/file_intents.hpp).
  struct FinishedRun {
    Job job;
    RunRecord record;
  };
  // Records, in a transaction of its own, that the result files `paths` are about to be
  // created (kind "import") or removed ("delete"); returns the intent's id.
  std::int64_t record_file_intent(const std::string& kind, const std::vector<std::string>& paths);
  void forget_file_intent(std::int64_t id);
  std::vector<FileIntent> file_intents();
  ResultReferences result_references();
  // Inserts finished runs from an archive (status, result and metrics as given) under their
  // ids and forgets the intent `intent` (0: none), all in one transaction; false (and
  // nothing changed) if one of the ids is taken. `also` (if given) writes more rows in the
  // same transaction (the study of a study's archive).
  bool insert_finished(const std::vector<FinishedRun>& runs, std::int64_t intent,
                       const std::function<void(Database&)>& also = {});

  std::string path() const { return db_.path(); }

  // The connection, shared with the other tables of the database (server/db/study_store.hpp).
  StoreDb& db() { return db_; }
  // On a connection of its own (the health check's): never waits behind a long listing
  // holding the connection's lock.
  std::int64_t user_version() { return db_.user_version(); }

private:
  std::optional<Job> query_one(const std::string& where, const std::vector<std::string>& args);
  // The metrics row of a finished run, from its record (finish(), insert_finished()).
  static void write_metrics(Database& db, const std::string& id, const RunRecord& record);

  StoreDb db_;
};

} // namespace slipfront::server
