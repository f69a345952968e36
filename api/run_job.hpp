// Run one validated job: the solver, the HDF5 result file and the metrics JSON.
// Shared by `slipfront run` and the server's workers.
#pragma once

#include "api/job_spec.hpp"
#include "api/run_record.hpp"
#include "solver/simulation.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace slipfront::api {

// What run_job returns: the solver's result in full (probes, energy records: what the CLI
// prints from) and the run's record (what the server stores and the report file carries).
struct JobOutput {
  RunResult result;
  RunRecord record;
};

// Runs the job. If output_path is not empty, the HDF5 file is written to a temporary file
// beside it and renamed into place only when the run ends with a result (not when it was
// cancelled or diverged: then no file is left behind). The record's status is cancelled when
// the cancel flag stopped the run, failed when it diverged, else succeeded; its metrics and
// front are metrics_json() and front_json() of the result, its wall time and end are left to
// the caller.
JobOutput run_job(const JobSpec& job, const std::string& output_path, const RunHooks& hooks = {});

// The metrics (docs/metrics.md "Metric names") as one JSON object (names are part of the API),
// including the cost (wall_time_s, steps, dt), mesh facts and the code version.
nlohmann::json metrics_json(const RunResult& result);

// As above, with "method" (the job field's spelling: "fe", "spectral_bi") and
// "method_description" naming the discretisation, its options and the friction law of
// `params` (run_job uses this one; the one-argument form names the method that ran,
// result.mesh.method, and its discretisation in a phrase).
nlohmann::json metrics_json(const RunResult& result, const SimulationParams& params);

// The numerical method that produced a result, e.g. "Q4 2x2 Gauss, lumped mass, central
// differences; top boundary: traction; friction: prakash_clifton, exponential strength update".
std::string method_description(const SimulationParams& params);

// The front (x1, arrival_time, rupture_speed) as JSON arrays; null where undefined.
nlohmann::json front_json(const RunResult& result);

} // namespace slipfront::api
