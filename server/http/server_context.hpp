// Everything the HTTP handlers use, owned by ServerApp. Handlers ask the services (jobs,
// studies), never the store, the queue or the running jobs directly.
#pragma once

#include "server/core/server_stats.hpp"
#include "server/http/auth.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_service.hpp"

#include <atomic>
#include <optional>
#include <string>

namespace slipfront::server {

struct ServerContext {
  JobService& service;
  ServerStats& stats;
  const std::optional<TokenTable>& tokens;
  std::string data_dir;
  int workers = 1; // the executor's slots: worker threads, or jobs kept in SLURM
  int retry_after_s = 30;
  std::atomic<bool>& draining;
  StudyService& studies;
  double min_free_bytes = 0.0;    // /healthz: degraded below this free space in data_dir
  std::string executor = "local"; // "local" or "slurm"
};

} // namespace slipfront::server
