// What a worker calls to run one job. The default, SolverJobRunner, runs the job's method
// (FE or spectral BI) through api::run_job; tests of the HTTP layer may inject another runner.
#pragma once

#include "server/core/job.hpp"
#include "server/core/run_record.hpp"
#include "solver/simulation.hpp"

#include <string>

namespace slipfront::server {

class JobRunner {
public:
  virtual ~JobRunner() = default;
  // Runs `job` writing its HDF5 result to `output_path`, and returns its record (result
  // path as given; the caller sets the wall time and the end). Status cancelled: the cancel
  // flag stopped the run. Throws on errors (the message becomes the job's error).
  virtual RunRecord run(const Job& job, const std::string& output_path, const RunHooks& hooks) = 0;
};

// Re-validates the stored canonical spec and runs it with api::run_job.
class SolverJobRunner : public JobRunner {
public:
  RunRecord run(const Job& job, const std::string& output_path, const RunHooks& hooks) override;
};

} // namespace slipfront::server
