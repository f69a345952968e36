// What the HTTP handlers ask of the server: submit, read, list and cancel jobs.
// Nothing here waits for a simulation: every call is a few short database operations.
#pragma once

#include "api/cost_estimate.hpp"
#include "api/job_spec.hpp"
#include "server/core/study.hpp"
#include "server/db/job_store.hpp"
#include "server/run/job_queue.hpp"
#include "server/run/running_jobs.hpp"
#include "server/services/result_files.hpp"

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

struct SubmitOptions {
  std::string user;                // who submits ("anonymous" without a token file)
  std::string idempotency_key;     // "" = none
  std::optional<bool> fresh;       // ?fresh=... (the body's "fresh" is read by submit())
  std::optional<int> priority;     // ?priority=...
  std::string study_id;            // the study submitting this job ("" = none)
  bool ignore_queue_limit = false; // runs a study adds later (its request was accepted)
};

struct SubmitResult {
  enum class Kind {
    created,      // 201: queued
    reused,       // 201: a succeeded job with the same physics and code version was reused
    replayed,     // 200: same Idempotency-Key as an earlier submission: that job
    bad_json,     // 400
    invalid,      // 422 (errors)
    key_conflict, // 422: Idempotency-Key reused with a different spec
    queue_full,   // 503
  } kind = Kind::created;
  std::vector<api::FieldError> errors;
  std::optional<Job> job;
};

// A job checked without submitting it (POST /jobs/validate).
struct CheckResult {
  enum class Kind {
    valid,    // 200
    bad_json, // 400
    invalid,  // 422 (errors)
  } kind = Kind::valid;
  std::vector<api::FieldError> errors;
  std::optional<api::JobSpec> spec;
  nlohmann::json validation; // validation_json() of the spec
};

struct CancelResult {
  enum class Kind {
    cancelled,        // it was queued: cancelled now
    cancel_requested, // running: it stops at its next step and ends cancelled
    finishing,        // its run has ended, its result is being stored: not cancelled
    not_found,
    forbidden,
    already_final,
  } kind;
  std::optional<Job> job;
};

// The answer to an owner's change to a run after submission (job_service_keep.cpp).
struct KeepResult {
  enum class Kind {
    done,
    not_found,
    forbidden, // a token file is configured and the run is another user's
    not_final, // delete: the run is queued or running (cancel it first)
    in_study,  // delete: a study holds the run (study_id); archive it instead
    invalid,   // the change cannot be made (error: its field and reason); nothing changed
  } kind = Kind::not_found;
  std::optional<Job> job; // done: the run as it is now (delete: as it was)
  std::string study_id;
  bool result_deleted = false; // delete: its result file went with it (no other run shares it)
  std::optional<api::FieldError> error; // invalid
};

// A finished run read from an archive and checked (server/http/run_archive.hpp), to be stored
// by JobService::import_runs.
struct RunToImport {
  Job job; // its id: the archive's, kept if free here
  RunRecord record;
  std::string_view result; // the result file's bytes ("" = none)
  std::string member;      // the archive member that holds them (for errors)
};

struct ImportResult {
  enum class Kind {
    imported, // every run stored
    no_space, // 503: the disk would fall below --min-free-bytes; nothing stored
    refused,  // 422: a result file is not what its run says (`where`: its member)
  } kind = Kind::imported;
  std::vector<std::pair<std::string, std::string>> ids; // (id here, id in the archive)
  // A run already here is not stored again (docs/server.md "Export and import").
  struct Skipped {
    std::string original_id; // in the archive
    std::string id;          // the run here that it is
    std::string reason;      // "same_origin" or "same_result"
    std::string detail;      // in words
  };
  std::vector<Skipped> skipped;
  // A study's archive: the study here (its id, the archive's; `skipped` when a study of that
  // id was here already: not stored again).
  struct ImportedStudy {
    std::string id, original_id;
    bool skipped = false;
  };
  std::optional<ImportedStudy> study;
  std::string where;
  std::string reason;
  std::vector<std::string> warnings; // what was left out of the runs (their metrics' names)
};

// What start-up found and removed in results/ (JobService::recover_result_files).
struct StrayResults {
  int intents = 0;                  // interrupted imports and deletes
  int undone = 0;                   // their files removed
  std::vector<StrayResult> removed; // other files no row referred to
};

struct ServiceOptions {
  double max_memory_bytes = 8.0e9;
  // The estimate of a job's wall time (api/cost_estimate.hpp) and the most it may be
  // (infinite: no limit).
  api::CostModel cost_model = api::CostModel::built_in();
  double max_run_seconds = std::numeric_limits<double>::infinity();
  double max_result_bytes = 20.0e9; // result-file estimate above which a job is refused
  std::string code_version;
  bool auth_enabled = false;
  // Result paths are relative to it; "" = the working directory. A cached result whose file
  // is gone or damaged (ResultFiles) is not reused.
  std::string data_dir;
  // Imports leave at least this much free space in the data dir (--min-free-bytes).
  double min_free_bytes = 0.0;
};

// The queue and the executor now, for /healthz and /metrics.
struct ServiceLoad {
  std::size_t running = 0;     // jobs running
  std::size_t queued = 0;      // jobs waiting in the run queue
  std::size_t queue_limit = 0; // queue size above which submissions get 503
};

class JobService {
public:
  JobService(ServiceOptions options, JobStore& store, JobQueue& queue, RunningJobs& running);

  SubmitResult submit(const std::string& body, const SubmitOptions& options);
  // The same for a parsed document (studies submit their runs through this).
  SubmitResult submit_document(nlohmann::json doc, const SubmitOptions& options);
  // Submits several jobs as one (a study with its first runs): f() runs holding the
  // submission lock, inside one database transaction (StoreDb::in_transaction). The jobs it
  // submits join the run queue only once that transaction commits; when f returns false or
  // throws, none of them stays, nor anything else f wrote. Within f the queue limit counts
  // the jobs f has submitted so far, so batches and single jobs together never pass it.
  // Returns whether f committed.
  bool submit_together(const std::function<bool()>& f);
  // Validates a job document as submit() would, without submitting it.
  api::ParseResult validate(nlohmann::json doc) const;
  // The same for a request body (with submit()'s server fields), and what the job record
  // would keep of the validation.
  CheckResult check(const std::string& body) const;
  // What a job record keeps of its validation: {"warnings", "provenance", "estimate"}.
  nlohmann::json validation_json(const api::JobSpec& spec) const;
  std::optional<Job> get(const std::string& id); // with live progress if running
  JobPage list(const JobFilter& filter);
  // The jobs of list(filter) one at a time, none kept (JobStore::scan): for exports.
  JobPage scan(const JobFilter& filter, const JobStore::EachJob& each);
  CancelResult cancel(const std::string& id, const std::string& user);
  // The stored rupture front of a job (null json if none); nullopt for an unknown job.
  std::optional<nlohmann::json> front(const std::string& id) { return store_.front(id); }

  // Owner-only changes after submission (docs/server.md "Keep, annotate, share").
  KeepResult annotate(const std::string& id, const std::string& user, const api::TagChange& tags,
                      const std::optional<std::string>& note);
  KeepResult set_archived(const std::string& id, const std::string& user, bool archived);
  // Deletes rows by `remove_rows` under the submission lock (no submission picks one of their
  // files as a cache hit meanwhile): one transaction that returns the result files no row
  // refers to any more and the intent to remove them; then removes those files and forgets
  // the intent. Returns how many files went. `what` names the change in the log.
  struct RowsRemoved {
    std::vector<std::string> orphaned_results;
    std::int64_t intent = 0;
  };
  std::size_t remove_rows_and_files(const std::function<RowsRemoved()>& remove_rows,
                                    const std::string& what);
  // Deletes a finished run; its result file too once no other run (a cache hit) refers to it.
  KeepResult remove(const std::string& id, const std::string& user);
  // Stores the runs of an archive for `user`, all of them or none (services/run_import.cpp):
  // each keeps its id if free here, else gets a new one. Each result file is opened with the
  // HDF5 API and checked against docs/hdf5-layout.md and the spec of its run before anything
  // is stored (refused otherwise). Throws StorageError when the disk refuses a write (nothing
  // stays).
  // A run already here is skipped, not stored again: one of the same origin (the server and id
  // that first computed it, followed through earlier imports) and spec, or one that succeeded
  // with the same result file (SHA-256) and spec.
  // `again`: store them all, those already here too (under new ids).
  // With `study`, the study is stored in the same transaction as its runs, listing each by
  // its id here (a run skipped as already here is listed as that run).
  ImportResult import_runs(std::vector<RunToImport> runs, const std::string& user,
                           bool again = false, std::optional<StudyToImport> study = std::nullopt);
  // At start-up, before the server answers: removes the files of imports and deletes a
  // crash interrupted, and every other file of results/ no row refers to.
  StrayResults recover_result_files();

  ServiceLoad load() const;
  // The number of jobs in the database by status.
  std::map<std::string, std::int64_t> count_by_status() { return store_.count_by_status(); }
  // Throws when the database does not answer a trivial query.
  void check_database() { store_.user_version(); }

  bool auth_enabled() const { return options_.auth_enabled; }
  // Called after a queued job was cancelled (a running one reports through the workers).
  void set_on_cancelled(std::function<void(const std::string& id)> f) {
    on_cancelled_ = std::move(f);
  }
  const ServiceOptions& options() const { return options_; }
  // The result files, verified before they are served (they may be hashed: off the I/O
  // threads).
  ResultFiles& result_files() { return result_files_; }

private:
  // A job inserted into the store goes to the run queue: at once, or at the commit of the
  // batch of submit_together(). The caller holds submit_mutex_.
  void enqueue(const std::string& id, int priority, bool ignore_queue_limit);
  bool queue_has_room() const; // counts the batch's jobs not queued yet

  struct Pending {
    std::string id;
    int priority = 0;
  };

  ServiceOptions options_;
  JobStore& store_;
  JobQueue& queue_;
  RunningJobs& running_;
  // Queue-limit check, insert and push are one step. Recursive: submit_together() holds it
  // while f() submits.
  std::recursive_mutex submit_mutex_;
  std::mutex import_mutex_; // one import at a time
  // `wanted` if neither a job, a result file nor `chosen` has it, else a new id.
  // The run here that `run` already is, and why; nullopt when there is none.
  std::optional<ImportResult::Skipped> already_here(const RunToImport& run);
  std::string free_import_id(const std::string& wanted, const std::set<std::string>& chosen);
  std::optional<std::vector<Pending>> batch_; // inside submit_together(): queued at its commit
  std::function<void(const std::string& id)> on_cancelled_;
  ResultFiles result_files_;
};

} // namespace slipfront::server
