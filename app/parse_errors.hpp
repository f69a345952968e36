// A command line that cannot be parsed, told in one line on stderr:
//   slipfront run: --threads needs an integer, got "many" (see slipfront run --help)
// whether the reason is the library's (a missing value or argument) or an option's own check.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

namespace slipfront::app {

// The reason of a CLI11 parse error of `command` in the words of the other messages:
// "missing JOB.json", "--csv needs a FILE".
std::string parse_error_reason(const CLI::App& command, const CLI::ParseError& error);

// Writes "COMMAND: REASON (see COMMAND --help)" to stderr; returns exit_code::bad_input.
int command_line_error(const CLI::App& command, const std::string& reason);

// What `command` left over (an unknown flag, a second file): the reason to refuse it, or ""
// when there is nothing.
std::string unexpected_arguments(const CLI::App& command);

} // namespace slipfront::app
