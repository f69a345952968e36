// The subcommands of the `slipfront` executable. Each takes the arguments after its own
// name and returns the process exit code.
#pragma once

#include <iosfwd>
#include <string>
#include <vector>

namespace slipfront::app {

namespace exit_code {
constexpr int success = 0;
constexpr int failure = 1;       // the run could not be carried out (I/O, internal error)
constexpr int bad_input = 2;     // invalid job or command line
constexpr int diverged = 3;      // the run ended with outcome "diverged"
constexpr int interrupted = 130; // SIGINT (128 + 2)
} // namespace exit_code

int run_command(const std::vector<std::string>& args);
int validate_command(const std::vector<std::string>& args);
int schema_command(const std::vector<std::string>& args);
int presets_command(const std::vector<std::string>& args);    // presets_command.cpp
int stations_command(const std::vector<std::string>& args);   // stations_command.cpp
int fit_length_command(const std::vector<std::string>& args); // fit_length_command.cpp
void print_usage(std::ostream& out);
void print_run_usage(std::ostream& out);
void print_validate_usage(std::ostream& out);
void print_presets_usage(std::ostream& out);    // presets_command.cpp
void print_stations_usage(std::ostream& out);   // stations_command.cpp
void print_fit_length_usage(std::ostream& out); // fit_length_command.cpp

// True if the arguments ask for help (--help or -h anywhere).
bool wants_help(const std::vector<std::string>& args);

} // namespace slipfront::app
