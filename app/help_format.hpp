// How `slipfront --help` and `slipfront COMMAND --help` look: a CLI11 formatter that writes
// the usage line from the options a command defines (so it lists every flag), the command's
// description, its arguments and options with their help, and its footer; the top level
// lists every command with its usage line and description.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace slipfront::app {

class HelpFormat : public CLI::FormatterBase {
public:
  std::string make_help(const CLI::App* command, std::string name,
                        CLI::AppFormatMode mode) const override;
};

// "slipfront run": the command's name after its parents'.
std::string command_path(const CLI::App& command);

// `prefix` then "slipfront run JOB.json [--output RESULT.h5] ...", wrapped at the help's
// width under the first argument. The options after `max_options` are shown as "[...]".
std::string usage_line(const CLI::App& command, const std::string& prefix,
                       std::size_t max_options = SIZE_MAX);

} // namespace slipfront::app
