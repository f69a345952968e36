// The run record: what one run of a job leaves behind, in the one shape that run_job returns
// (api/run_job.hpp), the report file carries from a compute node (api/run_files.hpp) and the
// server stores (its core names it: server/core/run_record.hpp).
#pragma once

#include "api/job_status.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>

namespace slipfront::api {

// A result file: where it is, its size and the SHA-256 of its bytes.
struct ResultFile {
  std::string path; // "" = none
  std::uint64_t size = 0;
  std::string sha256;
};

struct RunRecord {
  // succeeded; failed (diverged, or the run could not be carried out); cancelled (the cancel
  // flag stopped it: no result file is left).
  JobStatus status = JobStatus::succeeded;
  std::string error;      // why it failed or was cancelled; "" otherwise
  nlohmann::json metrics; // metrics_json() (api/run_job.hpp); null if none
  nlohmann::json front;   // front_json(); null if none
  ResultFile result;      // the HDF5 result file; empty path if none
  // Set by the server, which measures them: the run's wall time [s] and when it ended (ISO
  // 8601).
  double wall_time_s = 0.0;
  std::string finished_at;
};

// The error of a run that diverged, from the solver's message: "diverged: <message>".
std::string diverged_error(const std::string& message);

} // namespace slipfront::api
