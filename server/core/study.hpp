// A study as the server keeps it: its record (request, status, progress, the stored analysis)
// and its runs with what the jobs table knows of each (docs/studies-api.md).
#pragma once

#include "api/study/study_status.hpp"
#include "api/study_analysis.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace slipfront::server {

struct StudyRecord {
  std::int64_t seq = 0;
  std::string id;
  std::string name;
  std::vector<std::string> tags;
  std::string kind; // grid | convergence | failure_regimes
  nlohmann::json base;
  nlohmann::json request;
  std::string scene_hash; // of the base scene (the regularised one for the preset)
  std::string submitted_by;
  std::string idempotency_key; // "" = none (POST /studies' Idempotency-Key)
  int priority = 0;
  bool fresh = false;
  std::string created_at, updated_at, finished_at;
  api::StudyStatus status = api::StudyStatus::running;
  int runs_done = 0, runs_total = 0;
  double L_c = api::not_available;
  double spectral_critical_length = api::not_available;
  nlohmann::json result;   // the stored analysis (null until the first step)
  std::string note;        // its owner's free text (PATCH /studies/{id})
  std::string archived_at; // "" = listed; else hidden from GET /studies until asked for
};

// One run of a study with what the jobs table knows of it.
struct StudyRunRow {
  std::string job_id;
  std::string regime; // "" except for presets
  double L = 0.0, n_d = 0.0;
  std::string convergence_status = "pending";
  double partner_n_d = api::not_available;
  double propagation_distance_change = api::not_available;
  double arrival_time_change = api::not_available;
  std::string reason;
  // From jobs / metrics:
  std::string job_status;
  nlohmann::json metrics; // null if none
  double wall_time_s = 0.0;
  double memory_estimate_bytes = 0.0;
  std::string scene_hash, cached_from, result_path, submitted_by, study_id, error;
};

// A study read from an archive and checked (server/http/run_archive.hpp), to be stored with
// its runs (JobService::import_runs): its record and its runs by their ids in the archive.
struct StudyToImport {
  StudyRecord study;
  std::vector<StudyRunRow> runs;
};

// Wall time of what was computed: for a reused (cached) run, the original run's.
api::StudyRun to_study_run(const StudyRunRow& row);

} // namespace slipfront::server
