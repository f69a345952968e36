// The subcommands of the `slipfront` executable. Each add_*_command defines its command on
// the top-level CLI11 app (arguments, flags, help; one file each) and returns what runs it
// once the command line is parsed, returning the process exit code.
#pragma once

#include <CLI/CLI.hpp>

#include <functional>

namespace slipfront::app {

namespace exit_code {
constexpr int success = 0;
constexpr int failure = 1;       // the run could not be carried out (I/O, internal error)
constexpr int bad_input = 2;     // invalid job or command line
constexpr int diverged = 3;      // the run ended with outcome "diverged"
constexpr int interrupted = 130; // SIGINT (128 + 2)
} // namespace exit_code

// A command as main sees it: its place on the command line (to find which one was given) and
// what runs it with the parsed values, returning the process exit code.
struct Command {
  CLI::App* cli;
  std::function<int()> run;
};

Command add_run_command(CLI::App& slipfront);        // run_command.cpp
Command add_validate_command(CLI::App& slipfront);   // validate_command.cpp
Command add_schema_command(CLI::App& slipfront);     // schema_command.cpp
Command add_presets_command(CLI::App& slipfront);    // presets_command.cpp
Command add_stations_command(CLI::App& slipfront);   // stations_command.cpp
Command add_fit_length_command(CLI::App& slipfront); // fit_length_command.cpp
Command add_serve_command(CLI::App& slipfront);      // serve_command.cpp
Command add_check_command(CLI::App& slipfront);      // check_command.cpp
Command add_calibrate_command(CLI::App& slipfront);  // calibrate_command.cpp

} // namespace slipfront::app
