// Entry point of `slipfront check DATA_DIR`: reads a server's database without changing it and
// lists what a server could not read (docs/server.md, "Checking a data dir").
#pragma once

#include <string>

namespace slipfront::server {

// Prints "ok" and returns 0 when `PRAGMA quick_check` passes and every stored JSON parses;
// otherwise prints each problem (one line each) and returns 1 (also when DATA_DIR holds no
// database). Its command line: app/check_command.cpp.
int check_main(const std::string& data_dir);

} // namespace slipfront::server
