// The job record the server keeps for every submission, its states and their transitions.
#pragma once

#include "api/job_status.hpp"
#include "api/run_record.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::server {

// The job statuses and their names (api/job_status.hpp), shared with the study analysis.
using api::is_final;
using api::JobStatus;
using api::parse_status;
using api::to_string;

// A job's result file: path (relative to the data dir), size, SHA-256 (api/run_record.hpp).
using api::ResultFile;

// Where a job's result file is kept, relative to the data dir: results/<id>.h5.
inline std::string result_relative_path(const std::string& job_id) {
  return "results/" + job_id + ".h5";
}

enum class TransitionKind { normal, recovery };
bool transition_allowed(JobStatus from, JobStatus to, TransitionKind kind = TransitionKind::normal);

struct JobProgress {
  double fraction = 0.0;
  double time = 0.0;     // simulated time reached [s]
  double duration = 0.0; // simulated time requested [s]
  std::int64_t steps = 0;
  double eta_s = 0.0;
  std::string updated_at; // ISO 8601; "" = never
};

struct Job {
  std::int64_t seq = 0; // insertion order (SQLite rowid), the pagination cursor
  std::string id;       // 32 lower-case hex characters
  JobStatus status = JobStatus::queued;
  std::string name;
  std::vector<std::string> tags;
  nlohmann::json spec;     // canonical spec (every field present)
  std::string spec_sha256; // of the canonical physics
  std::string submitted_by;
  std::string idempotency_key;
  int priority = 0; // higher runs first; FIFO within a priority
  bool fresh = false;
  double L = 0.0;   // friction.L, for filtering
  double n_d = 0.0; // geometry.nodes_per_meter, for filtering
  double memory_estimate_bytes = 0.0;
  std::string created_at, started_at, finished_at; // ISO 8601; "" = not yet
  JobProgress progress;
  nlohmann::json metrics; // null until finished
  std::string error;
  double wall_time_s = 0.0;
  std::string code_version;
  std::string host;
  ResultFile result;
  std::string cached_from;      // id of the job whose result this one reuses
  int attempts = 0;             // how many times a worker started it
  std::string scene_hash;       // api::scene_hash of the spec: the convergence map it belongs to
  std::string study_id;         // the study that submitted it; "" = none
  std::string executor;         // "local" or "slurm" once started; "" = not yet
  std::string slurm_job_id;     // its SLURM job while it runs in SLURM (and after); "" = none
  std::string slurm_state;      // last SLURM state seen, with the reason: "PENDING (Resources)"
  std::string note;             // free text its owner keeps with it (api/run_annotations.hpp)
  std::string archived_at;      // ISO 8601 when archived (hidden from listings); "" = not archived
  nlohmann::json imported_from; // null, or {"server", "id", "exported_at"} of an imported run
  // Who imported its result file ("": this server computed it): an imported run's importer,
  // kept by its cache hits; such a result is a cache source for that user only.
  std::string result_imported_by;
  // What the validation said when the job was accepted: {"warnings", "provenance", "estimate"}
  // (api/scene_checks.hpp, api/scene_defaults.hpp); null for a job accepted before.
  nlohmann::json validation;
};

} // namespace slipfront::server
