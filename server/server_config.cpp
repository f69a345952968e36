#include "server/server_config.hpp"

#include "api/memory_size.hpp"

#include <nlohmann/json.hpp>

#include <unistd.h>

#include <charconv>
#include <fstream>
#include <functional>
#include <map>
#include <thread>

namespace slipfront::server {

std::string usage_text() {
  return "usage: slipfront serve [--host 127.0.0.1] [--port 8080] [--data-dir DIR]\n"
         "         [--workers N] [--queue-limit N] [--max-memory SIZE]\n"
         "         [--max-body-bytes N] [--max-unsent-bytes N] [--token-file F] [--config F]\n"
         "         [--io-threads N] [--max-exports N]\n"
         "         [--request-timeout-s S] [--retry-after-s S] [--db-progress-interval-s S]\n"
         "         [--min-free-bytes X] [--max-connections N] [--max-result-bytes X]\n"
         "         [--integrity-check on|off] [--web-dir DIR]\n"
         "         [--executor local|slurm] [--shared-dir DIR] [--slurm-partition P]\n"
         "         [--slurm-account A] [--slurm-time-limit T] [--slurm-sbatch-args ARGS]\n"
         "         [--slurm-binary PATH] [--slurm-max-jobs N] [--slurm-poll-interval-s S]\n"
         "see docs/server.md\n";
}

namespace {

template <class T> T parse_number(const std::string& flag, const std::string& text) {
  T value{};
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || end != text.data() + text.size())
    throw UsageError(flag + ": not a number: \"" + text + "\"");
  return value;
}

double memory_size(const std::string& flag, const std::string& text) {
  if (text == "0") return 0.0;
  auto bytes = api::parse_memory_size(text);
  if (!bytes)
    throw UsageError(flag + ": needs a size such as 8G or 500M (or 0 = automatic), got \"" + text +
                     "\"");
  return *bytes;
}

using Setter = std::function<void(ServerConfig&, const std::string& flag, const std::string&)>;

const std::map<std::string, Setter>& setters() {
  static const std::
      map<std::string, Setter>
          table =
              {
                  {"host",
                   [](ServerConfig& c, const std::string&, const std::string& v) { c.host = v; }},
                  {"port",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.port = parse_number<int>(f, v);
                     if (c.port < 0 || c.port > 65535)
                       throw UsageError(f + ": must be in [0, 65535]");
                   }},
                  {"data-dir", [](ServerConfig& c, const std::string&,
                                  const std::string& v) { c.data_dir = v; }},
                  {"workers",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.workers = parse_number<int>(f, v);
                     if (c.workers < 0 || c.workers > 1024)
                       throw UsageError(f + ": must be in [0, 1024]");
                   }},
                  {"queue-limit",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.queue_limit = parse_number<std::size_t>(f, v);
                   }},
                  // The name `run` and `validate` use; 0 = 3/4 of RAM / workers.
                  {"max-memory",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_memory_bytes = memory_size(f, v);
                   }},
                  // The old name, kept so that existing unit files and configs still start.
                  {"max-memory-bytes",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_memory_bytes = memory_size(f, v);
                   }},
                  {"max-result-bytes",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_result_bytes = parse_number<double>(f, v);
                     if (!(c.max_result_bytes > 0)) throw UsageError(f + ": must be > 0");
                   }},
                  {"max-body-bytes",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_body_bytes = parse_number<std::uint64_t>(f, v);
                   }},
                  {"max-unsent-bytes",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_unsent_bytes = parse_number<std::uint64_t>(f, v);
                     if (c.max_unsent_bytes < (1u << 20))
                       throw UsageError(f + ": must be >= 1 MiB");
                   }},
                  {"max-exports",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_exports = parse_number<int>(f, v);
                     if (c.max_exports < 1 || c.max_exports > 64)
                       throw UsageError(f + ": must be in [1, 64]");
                   }},
                  {"token-file", [](ServerConfig& c, const std::string&,
                                    const std::string& v) { c.token_file = v; }},
                  {"io-threads",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.io_threads = parse_number<int>(f, v);
                     if (c.io_threads < 1 || c.io_threads > 64)
                       throw UsageError(f + ": must be in [1, 64]");
                   }},
                  {"request-timeout-s",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.request_timeout_s = parse_number<int>(f, v);
                     if (c.request_timeout_s < 1) throw UsageError(f + ": must be >= 1");
                   }},
                  {"retry-after-s",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.retry_after_s = parse_number<int>(f, v);
                   }},
                  {"db-progress-interval-s",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.db_progress_interval_s = parse_number<double>(f, v);
                   }},
                  {"min-free-bytes",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.min_free_bytes = parse_number<double>(f, v);
                     if (!(c.min_free_bytes >= 0)) throw UsageError(f + ": must be >= 0");
                   }},
                  {"max-connections",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.max_connections = parse_number<int>(f, v);
                     if (c.max_connections < 1) throw UsageError(f + ": must be >= 1");
                   }},
                  {"executor",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     if (v != "local" && v != "slurm")
                       throw UsageError(f + ": must be local or slurm");
                     c.executor = v;
                   }},
                  {"shared-dir", [](ServerConfig& c, const std::string&,
                                    const std::string& v) { c.shared_dir = v; }},
                  {"slurm-partition", [](ServerConfig& c, const std::string&,
                                         const std::string& v) { c.slurm_partition = v; }},
                  {"slurm-account", [](ServerConfig& c, const std::string&,
                                       const std::string& v) { c.slurm_account = v; }},
                  {"slurm-time-limit", [](ServerConfig& c, const std::string&,
                                          const std::string& v) { c.slurm_time_limit = v; }},
                  {"slurm-sbatch-args", [](ServerConfig& c, const std::string&,
                                           const std::string& v) { c.slurm_sbatch_args = v; }},
                  {"slurm-binary",
                   [](ServerConfig& c, const std::string&,
                      const std::string& v) { c.slurm_binary = v; }},
                  {"slurm-max-jobs",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.slurm_max_jobs = parse_number<int>(f, v);
                     if (c.slurm_max_jobs < 1) throw UsageError(f + ": must be >= 1");
                   }},
                  {"slurm-poll-interval-s",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     c.slurm_poll_interval_s = parse_number<double>(f, v);
                     if (!(c.slurm_poll_interval_s >= 0.05))
                       throw UsageError(f + ": must be >= 0.05");
                   }},
                  {"web-dir", [](ServerConfig& c, const std::string&,
                                 const std::string& v) { c.web_dir = v; }},
                  {"integrity-check",
                   [](ServerConfig& c, const std::string& f, const std::string& v) {
                     if (v == "on" || v == "true")
                       c.integrity_check = true;
                     else if (v == "off" || v == "false")
                       c.integrity_check = false;
                     else
                       throw UsageError(f + ": must be on or off");
                   }},
              };
  return table;
}

} // namespace

void apply_config_file(const std::string& path, ServerConfig& config) {
  std::ifstream in(path);
  if (!in) throw UsageError("--config: cannot read " + path);
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(in);
  } catch (const std::exception& e) {
    throw UsageError("--config " + path + ": " + e.what());
  }
  if (!doc.is_object()) throw UsageError("--config " + path + ": must be a JSON object");
  for (auto& [key, value] : doc.items()) {
    std::string flag = key;
    for (char& c : flag)
      if (c == '_') c = '-';
    auto it = setters().find(flag);
    if (it == setters().end() || flag == "config")
      throw UsageError("--config " + path + ": unknown key \"" + key + "\"");
    std::string text = value.is_string() ? value.get<std::string>() : value.dump();
    it->second(config, path + ": " + key, text);
  }
}

ServerConfig parse_server_args(int argc, char** argv) {
  ServerConfig config;
  std::vector<std::pair<std::string, std::string>> flags;
  for (int i = 0; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg == "--help" || arg == "-h") throw UsageError("");
    if (arg.rfind("--", 0) != 0) throw UsageError("unexpected argument \"" + arg + "\"");
    std::string name = arg.substr(2), value;
    if (auto eq = name.find('='); eq != std::string::npos) {
      value = name.substr(eq + 1);
      name = name.substr(0, eq);
    } else {
      if (i + 1 >= argc) throw UsageError(arg + " needs a value");
      value = argv[++i];
    }
    if (name != "config" && !setters().count(name)) throw UsageError("unknown flag " + arg);
    flags.emplace_back(name, value);
  }
  for (auto& [name, value] : flags)
    if (name == "config") apply_config_file(value, config);
  for (auto& [name, value] : flags)
    if (name != "config") setters().at(name)(config, "--" + name, value);
  return config;
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
