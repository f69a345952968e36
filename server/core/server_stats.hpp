// Counters for GET /metrics (Prometheus text format): finished runs by status, run
// durations as a histogram, HTTP requests by status code.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace slipfront::server {

class ServerStats {
public:
  static constexpr std::array<double, 10> duration_buckets = {0.1, 0.5, 1,  2,   5,
                                                              10,  30,  60, 300, 1800};
  void record_run(const std::string& status, double wall_s);
  void record_request(unsigned status_code, double seconds);

  // The storage refused a write (disk full, I/O error): /healthz reports it for a while.
  struct StorageError {
    std::string message;
    std::string at;     // ISO 8601
    double age_s = 0.0; // seconds since
  };
  void record_storage_error(const std::string& message);
  std::optional<StorageError> last_storage_error() const;

  // Prometheus text of these counters (the gauges are added by the caller).
  std::string prometheus_text() const;

private:
  mutable std::mutex mutex_;
  std::map<std::string, std::uint64_t> finished_;
  std::array<std::uint64_t, duration_buckets.size()> run_buckets_{};
  std::uint64_t run_count_ = 0;
  double run_sum_ = 0.0;
  std::map<unsigned, std::uint64_t> requests_;
  double request_seconds_ = 0.0;
  std::optional<StorageError> storage_error_;
  std::uint64_t storage_errors_ = 0;
  std::chrono::steady_clock::time_point storage_error_time_;
};

} // namespace slipfront::server
