// `slipfront serve [--config F] [--host 127.0.0.1] [--port 8080] [--data-dir DIR] ...`: the
// HTTP job server (server/serve.hpp, docs/server.md). Its flags are the server's settings
// (server/server_config.hpp), one per setting; --max-memory and --cost-model are the flags run
// and validate take.
#include "app/commands.hpp"
#include "app/options.hpp"

#include "server/serve.hpp"
#include "server/server_config.hpp"

#include <memory>

namespace slipfront::app {

namespace {

// A setting's own check fails with server::UsageError: told like every command-line error.
template <class Apply> void as_parse_error(Apply apply) {
  try {
    apply();
  } catch (const server::UsageError& e) {
    throw CLI::ValidationError(e.what());
  }
}

} // namespace

Command add_serve_command(CLI::App& slipfront) {
  auto config = std::make_shared<server::ServerConfig>();
  CLI::App* command = add_command(
      slipfront, "serve",
      "Run the HTTP job server (docs/server.md): the web view at /, the API under /api/v1 "
      "(its OpenAPI document at /api/v1/openapi.json), jobs run by worker threads or by "
      "SLURM, the SQLite database and the HDF5 results in --data-dir. SIGTERM or SIGINT stop "
      "it (running jobs are queued again); SIGHUP reloads the token file.",
      "exit codes: 0 stopped by a signal, 1 could not start (the reason on stderr), 2 invalid "
      "command line or config file.");
  // CLI11 runs the options' callbacks in the order they are defined: the config file is read
  // first, and the flags given with it override its keys.
  command
      ->add_option_function<std::string>(
          "--config",
          [config](const std::string& path) {
            as_parse_error([&] { server::apply_config_file(path, *config); });
          },
          "a JSON file whose keys are these flags' names ('_' or '-'): {\"port\": 8080, "
          "\"data_dir\": \"/var/lib/slipfront\"}; the flags given override it")
      ->type_name("F");
  for (const server::ServerSetting& setting : server::server_settings()) {
    if (setting.name == "max-memory") {
      add_max_memory(*command, config->max_memory_bytes,
                     "3/4 of the physical memory shared by the workers", setting.old_name);
      continue;
    }
    if (setting.name == "cost-model") {
      add_cost_model(*command, config->cost_model_file,
                     "DATA_DIR/cost_model.json if it is there, else the built-in one");
      continue;
    }
    command
        ->add_option_function<std::string>(
            "--" + setting.name,
            [config, &setting](const std::string& text) {
              as_parse_error([&] { setting.set(*config, "--" + setting.name, text); });
            },
            setting.help)
        ->type_name(setting.value_name);
  }
  return {command, [config] { return server::serve_main(*config); }};
}

} // namespace slipfront::app
