// Entry point of `slipfront serve`: the HTTP job server (docs/server.md).
#pragma once

namespace slipfront::server {

// argv holds the arguments after the word "serve":
//   --host 127.0.0.1 --port 8080 --data-dir DIR --workers N --queue-limit N
//   --max-memory SIZE --max-body-bytes N --token-file F --config F
//   --executor local|slurm --shared-dir DIR --slurm-... (docs/cluster.md)
// Returns the process exit code. With --port 0 an ephemeral port is chosen and the bound
// address is printed on one line to stdout: "listening on http://127.0.0.1:PORT".
int serve_main(int argc, char** argv);

} // namespace slipfront::server
