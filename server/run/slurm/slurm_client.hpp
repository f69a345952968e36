// The SLURM commands the server needs on its (login) node: sbatch, squeue, sacct, scancel.
// Each call is one short program run with a time bound; nothing here keeps state.
#pragma once

#include "server/run/slurm/slurm_state.hpp"

#include <cstdint>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace slipfront::server {

struct SlurmSettings {
  std::string partition;  // --partition ("" = the cluster's default)
  std::string account;    // --account ("" = the user's default)
  std::string time_limit; // --time, in SLURM's syntax ("30", "2:00:00", "1-0"); "" = default
  std::vector<std::string> extra_sbatch_args; // e.g. {"--qos=long", "--constraint=avx512"}
  double command_timeout_s = 30.0;            // for each sbatch/squeue/sacct/scancel
};

// What one job asks of SLURM.
struct SbatchRequest {
  std::string job_name;    // "slipfront-<id>", never the client's name: what squeue shows
  std::string script_path; // the batch script (slurm_job_dir.hpp)
  std::string working_dir; // --chdir
  std::string log_path;    // --output (stdout and stderr of the batch script)
  int cpus = 1; // --cpus-per-task: the job's solver threads; 0 (all threads): --exclusive
  std::int64_t memory_mb = 0; // --mem
};

// A SLURM command failed. `transient`: the controller did not answer (retry later);
// otherwise SLURM refused the request (an invalid partition, account, limit...).
class SlurmError : public std::runtime_error {
public:
  SlurmError(const std::string& what, bool transient)
      : std::runtime_error(what), transient_(transient) {}
  bool transient() const { return transient_; }

private:
  bool transient_;
};

class SlurmClient {
public:
  explicit SlurmClient(SlurmSettings settings) : settings_(std::move(settings)) {}

  // The sbatch command line for a request (without running it).
  std::vector<std::string> sbatch_command(const SbatchRequest& request) const;
  // Submits; returns the SLURM job id. Throws SlurmError.
  std::string submit(const SbatchRequest& request) const;
  // Every job of this user that the controller still knows (squeue --me -t all: running,
  // waiting, and ended within its MinJobAge). Throws SlurmError if squeue fails.
  std::map<std::string, SlurmJobState> query() const;
  // The accounting database's states of these jobs (sacct); empty where accounting is off.
  std::map<std::string, SlurmJobState> query_accounting(const std::vector<std::string>& ids) const;
  // scancel. Throws SlurmError.
  void cancel(const std::string& job_id) const;

  const SlurmSettings& settings() const { return settings_; }

private:
  SlurmSettings settings_;
};

// Whether sbatch's complaint means "try again later" (controller down or busy) rather than
// "this request will never be accepted".
bool is_transient_slurm_error(const std::string& message);

} // namespace slipfront::server
