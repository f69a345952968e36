// The runs a study analyses (docs/studies.md): one job of a study as the server knows it, and the
// tolerances of the mesh-convergence criterion.
#pragma once

#include "api/job_status.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// One run of a study, as the server knows it.
struct StudyRun {
  std::string id;
  double L = 0.0;   // friction.L (m)
  double n_d = 0.0; // geometry.nodes_per_meter
  JobStatus status = JobStatus::queued;
  std::optional<nlohmann::json> metrics; // the metrics JSON (docs/metrics.md), when it has one
  double wall_time_s = 0.0;
  double memory_bytes = 0.0;
};

// The runs of one scene by one method, named by the job's spelling ("fe", "spectral_bi"): a
// side of a comparison across methods.
struct MethodRuns {
  std::string method;
  const std::vector<StudyRun>& runs;
};

// docs/metrics.md "Convergence status", paper §3.1: refining the mesh changes propagation_distance
// by < 0.5 % and arrival_time_at_probe by < 0.1 %. Relative changes, strict inequalities.
struct ConvergenceTolerances {
  double propagation_distance = 0.005;
  double arrival_time = 0.001;
};

constexpr double not_available = std::numeric_limits<double>::quiet_NaN();

} // namespace slipfront::api
