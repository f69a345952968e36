#include "server/server_config.hpp"

#include "api/memory_size.hpp"
#include "api/number_text.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <optional>
#include <thread>

namespace slipfront::server {

namespace {

using Setter = std::function<void(ServerConfig&, const std::string&, const std::string&)>;

template <class T> std::string shown(T value) {
  if constexpr (std::is_floating_point_v<T>)
    return api::number_text(value);
  else
    return std::to_string(value);
}

// A number of type T in [min, max] (either bound optional); integers are whole, real numbers
// finite.
template <class T>
T parse_number(const std::string& where, const std::string& text, std::optional<T> min,
               std::optional<T> max) {
  T value{};
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec == std::errc::result_out_of_range)
    throw UsageError(where + ": " + text + " is out of range");
  if (ec != std::errc() || end != text.data() + text.size())
    throw UsageError(where + ": not a number: \"" + text + "\"");
  if constexpr (std::is_floating_point_v<T>)
    if (!std::isfinite(value)) throw UsageError(where + ": must be finite, got " + text);
  if (min && max && (value < *min || value > *max))
    throw UsageError(where + ": must be in [" + shown(*min) + ", " + shown(*max) + "], got " +
                     text);
  if (min && value < *min)
    throw UsageError(where + ": must be >= " + shown(*min) + ", got " + text);
  return value;
}

template <class T>
Setter number(T ServerConfig::*field, std::optional<T> min = std::nullopt,
              std::optional<T> max = std::nullopt) {
  return [=](ServerConfig& c, const std::string& where, const std::string& text) {
    c.*field = parse_number<T>(where, text, min, max);
  };
}

Setter text(std::string ServerConfig::*field) {
  return [=](ServerConfig& c, const std::string&, const std::string& text) { c.*field = text; };
}

// The size that `run` and `validate` take (api/memory_size.hpp); 0 = 3/4 of RAM / workers.
void set_max_memory(ServerConfig& c, const std::string& where, const std::string& text) {
  if (text == "0") {
    c.max_memory_bytes = 0.0;
    return;
  }
  const std::optional<double> bytes = api::parse_memory_size(text);
  if (!bytes) throw UsageError(where + " " + api::memory_size_expected(text));
  c.max_memory_bytes = *bytes;
}

void set_max_result_bytes(ServerConfig& c, const std::string& where, const std::string& text) {
  c.max_result_bytes = parse_number<double>(where, text, std::nullopt, std::nullopt);
  if (!(c.max_result_bytes > 0)) throw UsageError(where + ": must be > 0, got " + text);
}

void set_executor(ServerConfig& c, const std::string& where, const std::string& text) {
  if (text != "local" && text != "slurm")
    throw UsageError(where + ": must be local or slurm, got \"" + text + "\"");
  c.executor = text;
}

void set_integrity_check(ServerConfig& c, const std::string& where, const std::string& text) {
  if (text == "on" || text == "true")
    c.integrity_check = true;
  else if (text == "off" || text == "false")
    c.integrity_check = false;
  else
    throw UsageError(where + ": must be on or off, got \"" + text + "\"");
}

} // namespace

// The defaults below are ServerConfig's (server_config.hpp); docs/server.md and
// docs/cluster.md explain each setting at length.
const std::vector<ServerSetting>& server_settings() {
  static const std::vector<ServerSetting> settings = {
      {"host", "ADDRESS",
       "address to bind (default 127.0.0.1; keep loopback behind a reverse proxy)",
       text(&ServerConfig::host)},
      {"port", "N",
       "port (default 8080); 0 picks a free one, printed as \"listening on http://HOST:PORT\"",
       number<int>(&ServerConfig::port, 0, 65535)},
      {"data-dir", "DIR", "database slipfront.db and results/ (default slipfront-data)",
       text(&ServerConfig::data_dir)},
      {"workers", "N", "simulations run at once (default 0: one per core)",
       number<int>(&ServerConfig::workers, 0, 1024)},
      {"queue-limit", "N", "queued jobs above which POST /jobs answers 503 (default 1000)",
       number<std::size_t>(&ServerConfig::queue_limit)},
      // The flag's definition is the one `run` and `validate` share (app/options.cpp); this
      // entry is the config file's key and the help of the old name.
      {"max-memory", "SIZE",
       "refuse a job whose memory estimate is above SIZE (default 0: 3/4 of the physical "
       "memory shared by the workers)",
       set_max_memory, "max-memory-bytes"},
      {"max-result-bytes", "X",
       "refuse a job whose result file is estimated above X bytes (default 20e9)",
       set_max_result_bytes},
      {"max-run-seconds", "S",
       "refuse a job whose estimated wall time on this server is above S seconds (default "
       "604800, a week; 0: no limit)",
       number<double>(&ServerConfig::max_run_seconds, 0.0)},
      {"cost-model", "F",
       "the cost model of the estimates (default DATA_DIR/cost_model.json, written by "
       "slipfront calibrate; without it the built-in one)",
       text(&ServerConfig::cost_model_file)},
      {"max-body-bytes", "N", "larger request bodies get 413 (default 1 MiB)",
       number<std::uint64_t>(&ServerConfig::max_body_bytes)},
      {"max-import-bytes", "N",
       "larger run archives (POST /imports) get 413 (default 1 GiB, held in memory)",
       number<std::uint64_t>(&ServerConfig::max_import_bytes, std::uint64_t{1} << 20)},
      {"max-unsent-bytes", "N",
       "answers built in memory and not yet read, over all connections (default 256 MiB, at "
       "least 1 MiB)",
       number<std::uint64_t>(&ServerConfig::max_unsent_bytes, std::uint64_t{1} << 20)},
      {"max-exports", "N",
       "run-table exports (GET /jobs?format=csv|ndjson) at once; more get 503 (default 2)",
       number<int>(&ServerConfig::max_exports, 1, 64)},
      {"max-fits", "N",
       "length fits (POST /length-fits) at once, on threads of their own; more get 503 "
       "(default 2)",
       number<int>(&ServerConfig::max_fits, 1, 64)},
      {"max-export-bytes", "N",
       "disk taken by run archives (GET /exports) not yet sent, over all clients; past it 503 "
       "(default 8 GiB, at least 1 MiB)",
       number<std::uint64_t>(&ServerConfig::max_export_bytes, std::uint64_t{1} << 20)},
      {"token-file", "F", "bearer tokens to submit and cancel (default none: no authentication)",
       text(&ServerConfig::token_file)},
      {"io-threads", "N", "threads answering HTTP (default 2)",
       number<int>(&ServerConfig::io_threads, 1, 64)},
      {"request-timeout-s", "S",
       "a request must arrive within S seconds; idle connections close after it (default 30)",
       number<int>(&ServerConfig::request_timeout_s, 1)},
      {"send-timeout-s", "S",
       "a client that takes no byte of an answer for S seconds is disconnected (default 30)",
       number<int>(&ServerConfig::send_timeout_s, 1)},
      {"retry-after-s", "S", "Retry-After of 503 answers (default 30)",
       number<int>(&ServerConfig::retry_after_s, 0)},
      {"db-progress-interval-s", "S",
       "how often a running job's progress is written to the database (default 3)",
       number<double>(&ServerConfig::db_progress_interval_s, 0.0)},
      {"min-free-bytes", "X",
       "/healthz is degraded below X bytes free in the data dir (default 64 MiB)",
       number<double>(&ServerConfig::min_free_bytes, 0.0)},
      {"max-connections", "N", "connections open at once; more get 503 (default 256)",
       number<int>(&ServerConfig::max_connections, 1)},
      {"integrity-check", "on|off", "PRAGMA quick_check of the database at start (default on)",
       set_integrity_check},
      {"web-dir", "DIR",
       "the web view's files (default: share/slipfront/web beside the executable)",
       text(&ServerConfig::web_dir)},
      {"executor", "local|slurm",
       "where jobs run: the worker threads, or one sbatch job per run (docs/cluster.md)",
       set_executor},
      {"shared-dir", "DIR",
       "slurm: directory shared with the compute nodes (default DATA_DIR/slurm)",
       text(&ServerConfig::shared_dir)},
      {"slurm-partition", "P", "slurm: sbatch --partition (default: the cluster's)",
       text(&ServerConfig::slurm_partition)},
      {"slurm-account", "A", "slurm: sbatch --account (default: the user's)",
       text(&ServerConfig::slurm_account)},
      {"slurm-time-limit", "T", "slurm: sbatch --time (default: the partition's)",
       text(&ServerConfig::slurm_time_limit)},
      {"slurm-sbatch-args", "ARGS",
       "slurm: more sbatch options, separated by spaces: --slurm-sbatch-args \"--qos=long "
       "--constraint=avx512\"",
       text(&ServerConfig::slurm_sbatch_args)},
      {"slurm-binary", "PATH", "slurm: slipfront on the compute nodes (default: this executable)",
       text(&ServerConfig::slurm_binary)},
      {"slurm-max-jobs", "N", "slurm: jobs kept in SLURM at once (default 100)",
       number<int>(&ServerConfig::slurm_max_jobs, 1)},
      {"slurm-poll-interval-s", "S",
       "slurm: how often squeue and progress files are read (default 2)",
       number<double>(&ServerConfig::slurm_poll_interval_s, 0.05)},
  };
  return settings;
}

void apply_config_file(const std::string& path, ServerConfig& config) {
  std::ifstream in(path);
  if (!in) throw UsageError("--config: cannot read " + path + ": " + std::strerror(errno));
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw UsageError("--config " + path + ": " + e.what());
  }
  if (!doc.is_object()) throw UsageError("--config " + path + ": must be a JSON object");
  for (auto& [key, value] : doc.items()) {
    std::string name = key;
    for (char& c : name)
      if (c == '_') c = '-';
    const ServerSetting* setting = nullptr;
    for (const ServerSetting& s : server_settings())
      if (s.name == name || (!s.old_name.empty() && s.old_name == name)) setting = &s;
    if (setting == nullptr) throw UsageError("--config " + path + ": unknown key \"" + key + "\"");
    const std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    setting->set(config, path + ": " + key, text);
  }
}

void resolve_defaults(ServerConfig& config) {
  if (config.workers == 0)
    config.workers = std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  if (config.max_memory_bytes == 0.0) {
    double physical =
        static_cast<double>(sysconf(_SC_PHYS_PAGES)) * static_cast<double>(sysconf(_SC_PAGESIZE));
    config.max_memory_bytes = physical > 0 ? 0.75 * physical / config.workers : 8.0e9;
  }
}

} // namespace slipfront::server
