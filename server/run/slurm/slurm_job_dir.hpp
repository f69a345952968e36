// One job's directory on the shared file system, <shared-dir>/jobs/<id>/: what the server
// writes before sbatch (the spec and the batch script) and what the run writes back on the
// compute node (progress, report, result, exit code, SLURM's log). Compute nodes never
// touch the database: these files are all they share with the server.
#pragma once

#include "server/core/job.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace slipfront::server {

class SlurmJobDir {
public:
  SlurmJobDir(const std::string& shared_dir, const std::string& job_id);

  const std::string& path() const { return path_; }
  std::string file(const char* name) const { return path_ + "/" + name; }
  std::string spec() const { return file("spec.json"); }
  std::string script() const { return file("job.sh"); }
  std::string progress() const { return file("progress.json"); }
  std::string report() const { return file("report.json"); }
  std::string result() const { return file("result.h5"); }
  std::string exit_code() const { return file("exit_code"); }
  std::string log() const { return file("slurm.out"); }

  // Creates the directory (emptied of an earlier attempt's files) with spec.json and job.sh:
  // `binary run spec.json --output result.h5 --progress-file ... --report-file ...`, then
  // the exit status into exit_code. The script holds no text from the client (not the job's
  // name or tags: those are in spec.json). Throws std::runtime_error naming the path, or if
  // the job's id is not one the server makes.
  void prepare(const Job& job, const std::string& binary, double max_memory_bytes) const;

  // The progress the run last wrote; nullopt if none yet or unreadable (being replaced).
  std::optional<JobProgress> read_progress() const;
  // The report (api/run_files.hpp); nullopt if the run has not written one.
  // Throws if it exists but is not a report.
  std::optional<nlohmann::json> read_report() const;
  // The batch script's recorded exit status of `slipfront run`; nullopt if not written.
  std::optional<int> read_exit_code() const;
  // The last lines of SLURM's log of the batch script (stderr of slipfront run).
  std::string log_tail(std::size_t max_bytes = 600) const;

  void remove() const; // best effort: the directory and its files

private:
  std::string path_;
};

// `text` quoted for /bin/sh.
std::string shell_quote(const std::string& text);

// The memory a job asks SLURM for: its estimate, plus a quarter and 256 MiB for the
// process, the HDF5 library and the result buffers; in MiB.
std::int64_t slurm_memory_mb(double memory_estimate_bytes);

} // namespace slipfront::server
