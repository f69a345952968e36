#include "server/core/server_stats.hpp"

#include "server/core/clock.hpp"

#include <sstream>

namespace slipfront::server {

void ServerStats::record_run(const std::string& status, double wall_s) {
  std::lock_guard lock(mutex_);
  ++finished_[status];
  ++run_count_;
  run_sum_ += wall_s;
  for (std::size_t i = 0; i < duration_buckets.size(); ++i)
    if (wall_s <= duration_buckets[i]) ++run_buckets_[i];
}

void ServerStats::record_request(unsigned status_code, double seconds) {
  std::lock_guard lock(mutex_);
  ++requests_[status_code];
  request_seconds_ += seconds;
}

void ServerStats::record_storage_error(const std::string& message) {
  std::lock_guard lock(mutex_);
  storage_error_ = StorageError{message, now_iso8601(), 0.0};
  storage_error_time_ = std::chrono::steady_clock::now();
  ++storage_errors_;
}

std::optional<ServerStats::StorageError> ServerStats::last_storage_error() const {
  std::lock_guard lock(mutex_);
  if (!storage_error_) return std::nullopt;
  StorageError e = *storage_error_;
  e.age_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - storage_error_time_).count();
  return e;
}

std::string ServerStats::prometheus_text() const {
  std::lock_guard lock(mutex_);
  std::ostringstream out;
  out << "# HELP slipfront_runs_finished_total Runs finished by this process, by final status.\n"
      << "# TYPE slipfront_runs_finished_total counter\n";
  for (const char* s : {"succeeded", "failed", "cancelled", "requeued"}) {
    auto it = finished_.find(s);
    out << "slipfront_runs_finished_total{status=\"" << s << "\"} "
        << (it == finished_.end() ? 0 : it->second) << "\n";
  }
  out << "# HELP slipfront_run_duration_seconds Wall time of runs finished by this process.\n"
      << "# TYPE slipfront_run_duration_seconds histogram\n";
  for (std::size_t i = 0; i < duration_buckets.size(); ++i)
    out << "slipfront_run_duration_seconds_bucket{le=\"" << duration_buckets[i] << "\"} "
        << run_buckets_[i] << "\n";
  out << "slipfront_run_duration_seconds_bucket{le=\"+Inf\"} " << run_count_ << "\n"
      << "slipfront_run_duration_seconds_sum " << run_sum_ << "\n"
      << "slipfront_run_duration_seconds_count " << run_count_ << "\n";
  out << "# HELP slipfront_http_requests_total HTTP requests answered, by status code.\n"
      << "# TYPE slipfront_http_requests_total counter\n";
  for (auto& [code, n] : requests_)
    out << "slipfront_http_requests_total{code=\"" << code << "\"} " << n << "\n";
  out << "# HELP slipfront_http_request_seconds_total Time spent handling HTTP requests.\n"
      << "# TYPE slipfront_http_request_seconds_total counter\n"
      << "slipfront_http_request_seconds_total " << request_seconds_ << "\n"
      << "# HELP slipfront_storage_errors_total Writes the storage refused (disk full, I/O).\n"
      << "# TYPE slipfront_storage_errors_total counter\n"
      << "slipfront_storage_errors_total " << storage_errors_ << "\n";
  return out.str();
}

} // namespace slipfront::server
