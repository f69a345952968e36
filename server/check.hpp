// Entry point of `slipfront check DATA_DIR`: reads a server's database and result files without
// changing them and lists what a server could not read or would remove (docs/server.md,
// "Checking a data dir").
#pragma once

#include <string>

namespace slipfront::server {

// Prints "ok" and returns 0 when `PRAGMA quick_check` passes, every stored JSON parses and
// every file of DATA_DIR/results has a job that refers to it (or is a queued or running
// job's); otherwise prints each problem (one line each) and returns 1 (also when DATA_DIR
// holds no database). Its command line: app/check_command.cpp.
int check_main(const std::string& data_dir);

} // namespace slipfront::server
