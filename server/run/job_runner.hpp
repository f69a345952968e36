// What a worker calls to run one job. The default, SolverJobRunner, runs the FE solver
// through api::run_job; tests of the HTTP layer may inject another runner.
#pragma once

#include "api/metrics_row.hpp"
#include "server/core/job.hpp"
#include "solver/simulation.hpp"

#include <nlohmann/json.hpp>

#include <memory>
#include <optional>
#include <string>

namespace slipfront::server {

struct RunReport {
  bool cancelled = false; // the cancel flag stopped the run (no result file is left)
  bool failed = false;    // the run ended without a usable result (e.g. diverged)
  std::string error;      // why it failed
  nlohmann::json metrics; // null if none
  nlohmann::json front;   // null if none
  ResultFile result;      // path as given to run(), size and sha256; empty path if none
  // The metrics row columns, from the solver Metrics; unset: read from `metrics`.
  std::optional<api::MetricsRow> metrics_row;
};

class JobRunner {
public:
  virtual ~JobRunner() = default;
  // Runs `job` writing its HDF5 result to `output_path`. Throws on errors (the message
  // becomes the job's error).
  virtual RunReport run(const Job& job, const std::string& output_path, const RunHooks& hooks) = 0;
};

// Re-validates the stored canonical spec and runs it with api::run_job.
class SolverJobRunner : public JobRunner {
public:
  RunReport run(const Job& job, const std::string& output_path, const RunHooks& hooks) override;
};

} // namespace slipfront::server
