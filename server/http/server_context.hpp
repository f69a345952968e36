// Everything the HTTP handlers use, owned by ServerApp. Handlers ask the services (jobs,
// studies), never the store, the queue or the running jobs directly.
#pragma once

#include "server/core/byte_budget.hpp"
#include "server/core/server_stats.hpp"
#include "server/http/auth.hpp"
#include "server/services/job_service.hpp"
#include "server/services/study_service.hpp"

#include <atomic>
#include <cstdint>
#include <memory>
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
  // The disk of run archives built and not yet sent (--max-export-bytes): each reserves its
  // size before it is written and releases it when its file is closed.
  std::shared_ptr<ByteBudget> export_bytes = std::make_shared<ByteBudget>(std::uint64_t{8} << 30);
};

} // namespace slipfront::server
