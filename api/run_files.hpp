// The files a run writes for whoever follows it from another process or machine (the
// server's SLURM executor follows `slipfront run` on a compute node through them):
//   progress file  rewritten about twice a second: {fraction, time, duration, steps, eta_s}
//   report file    written once at the end: {metrics, front, result_file, diverged, message}
// Both are JSON written to a temporary name beside the target and renamed into place, so a
// reader (also over a shared file system) never sees half a file.
#pragma once

#include "api/run_record.hpp"
#include "solver/run/run_hooks.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace slipfront::api {

struct JobOutput;

nlohmann::json progress_json(const Progress& progress);

// The report of a finished run (not written for a cancelled run or an I/O failure): the run
// record's metrics, front and result file, and whether it diverged with the solver's message.
nlohmann::json run_report_json(const JobOutput& output);
// The run record a report carries (status failed when it diverged, else succeeded); the
// wall time and the end are left to the reader.
RunRecord run_record_of_report(const nlohmann::json& report);

// Writes `doc` to `path` atomically (temporary file + rename; `durable` adds an fsync before
// the rename, for the report). Throws std::runtime_error naming the path and the error.
void write_json_atomically(const std::string& path, const nlohmann::json& doc, bool durable = true);

} // namespace slipfront::api
