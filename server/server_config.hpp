// The server's settings: defaults, then a JSON config file (--config), then flags. Each
// setting is described once (server_settings()): its name, the help of its flag and how its
// value is read; `slipfront serve` (app/serve_command.cpp) makes its flags from that table
// and the config file takes the same keys.
#pragma once

#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace slipfront::server {

struct ServerConfig {
  std::string host = "127.0.0.1";
  int port = 8080; // 0 = an ephemeral port
  std::string data_dir = "slipfront-data";
  int workers = 0;                  // 0 = one per hardware thread
  std::size_t queue_limit = 1000;   // queued jobs above which POST /jobs answers 503
  double max_memory_bytes = 0.0;    // 0 = 3/4 of physical memory shared by the workers
  double max_result_bytes = 20.0e9; // a job whose result-file estimate is above is refused
  // A job whose estimated wall time on this server is above is refused (0 = no limit); the
  // cost model (docs/performance.md "Cost estimate") is read from cost_model_file, by default
  // DATA_DIR/cost_model.json (`slipfront calibrate` writes it), else the built-in one.
  double max_run_seconds = 7 * 86400.0;
  std::string cost_model_file;
  std::uint64_t max_body_bytes = 1 << 20;
  // The body of POST /imports (a tar of runs, held in memory while it is checked).
  std::uint64_t max_import_bytes = std::uint64_t{1} << 30;
  // Answers built in memory and not yet read by their clients, over all connections.
  std::uint64_t max_unsent_bytes = std::uint64_t{256} << 20;
  // Run-table exports (GET /jobs?format=csv|ndjson) at once; more are answered 503.
  int max_exports = 2;
  // Length fits (POST /length-fits) at once; more are answered 503.
  int max_fits = 2;
  // The disk taken by run archives (GET /exports) built and not yet sent, over all clients.
  std::uint64_t max_export_bytes = std::uint64_t{8} << 30;
  std::string token_file;     // "" = no authentication
  int io_threads = 2;         // threads answering HTTP
  int request_timeout_s = 30; // to receive a request; idle keep-alive connections
  int send_timeout_s = 30;    // a client that takes no byte of an answer for this long is cut
  int retry_after_s = 30;     // Retry-After of 503 answers
  double db_progress_interval_s = 3.0;
  double min_free_bytes = 64.0 * 1024 * 1024; // /healthz is degraded below this free space
  bool integrity_check = true;                // PRAGMA quick_check of the database at start
  int max_connections = 256; // open connections; more are answered 503 and closed at once

  // Where jobs run (docs/cluster.md): "local" (worker threads) or "slurm" (sbatch).
  std::string executor = "local";
  std::string shared_dir;       // slurm: job files, seen by the compute nodes ("" = data dir/slurm)
  std::string slurm_partition;  // "" = the cluster's default
  std::string slurm_account;    // "" = the user's default
  std::string slurm_time_limit; // sbatch --time ("" = the partition's default)
  std::string slurm_sbatch_args;      // more sbatch options, separated by spaces
  std::string slurm_binary;           // slipfront on the compute nodes ("" = this executable)
  int slurm_max_jobs = 100;           // jobs kept in SLURM at once
  double slurm_poll_interval_s = 2.0; // squeue and progress files
  std::string web_dir; // the web view's files; "" = beside the executable (docs/web.md)
};

// A value the server cannot take: the reason names the flag or the config file's key.
class UsageError : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

// One setting: the flag `--NAME` (and the config file's key NAME, with '_' for '-').
struct ServerSetting {
  std::string name;       // "port"
  std::string value_name; // "N", shown in the help: --port N
  std::string help;       // its line in `slipfront serve --help`, with the default
  // Reads `text` into the config; throws UsageError naming `where` (the flag or the key).
  std::function<void(ServerConfig&, const std::string& where, const std::string& text)> set;
  std::string old_name = ""; // a former name still accepted ("max-memory-bytes")
};

// Every setting, in the order `slipfront serve --help` lists them.
const std::vector<ServerSetting>& server_settings();

// Keys of the config file: the flag names with '_' for '-', e.g. {"port": 8080,
// "data_dir": "/var/lib/slipfront", "workers": 4}. Unknown keys are errors.
void apply_config_file(const std::string& path, ServerConfig& config);

// Fills the 0 defaults (workers, memory limit) from the machine.
void resolve_defaults(ServerConfig& config);

} // namespace slipfront::server
