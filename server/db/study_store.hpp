// The studies and study_runs tables (migration 2 -> 3, server/db/migrations/m3_studies.cpp),
// in the jobs database, on its shared connection (server/db/store_db.hpp). Convergence statuses,
// L_c and the analysis JSON are stored when a run of the study finishes (StudySupervisor), so
// reading a study is a few indexed SELECTs.
#pragma once

#include "api/study/study_status.hpp"
#include "api/study_analysis.hpp"
#include "server/db/job_store.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
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
  int priority = 0;
  bool fresh = false;
  std::string created_at, updated_at, finished_at;
  api::StudyStatus status = api::StudyStatus::running;
  int runs_done = 0, runs_total = 0;
  double L_c = api::not_available;
  double spectral_critical_length = api::not_available;
  nlohmann::json result; // the stored analysis (null until the first step)
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

// Wall time of what was computed: for a reused (cached) run, the original run's.
api::StudyRun to_study_run(const StudyRunRow& row);

class StudyStore {
public:
  explicit StudyStore(JobStore& jobs) : db_(jobs.db()) {}

  void insert(const StudyRecord& study);
  void add_run(const std::string& study_id, const std::string& job_id, const std::string& regime,
               double L, double n_d);
  std::optional<StudyRecord> get(const std::string& id);
  // Newest first; `before_seq` is the cursor of the previous page.
  std::vector<StudyRecord> list(int limit, std::optional<std::int64_t> before_seq,
                                std::optional<api::StudyStatus> status);
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

  // Stores the statuses of `runs` (by job id) and the study's summary in one transaction.
  void save_analysis(const StudyRecord& study, const std::vector<StudyRunRow>& runs);

private:
  StoreDb& db_;
};

} // namespace slipfront::server
