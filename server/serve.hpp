// Entry point of `slipfront serve`: the HTTP job server (docs/server.md).
#pragma once

#include "server/server_config.hpp"

namespace slipfront::server {

// Runs the server with `config` (its flags: app/serve_command.cpp) until SIGTERM or SIGINT.
// Returns the process exit code. With --port 0 an ephemeral port is chosen and the bound
// address is printed on one line to stdout: "listening on http://127.0.0.1:PORT".
int serve_main(const ServerConfig& config);

} // namespace slipfront::server
