// The `slipfront` executable: run, validate, schema, presets, stations, fit-length, serve, check
// (docs/api-job-spec.md "The CLI", docs/server.md). One CLI11 command line: each command
// defines its arguments and flags in its own file (app/commands.hpp), the flags several
// commands share in app/options.cpp, the help's look in app/help_format.cpp.
#include "app/commands.hpp"
#include "app/help_format.hpp"
#include "app/parse_errors.hpp"

#include "solver/simulation.hpp"

#include <iostream>
#include <map>
#include <memory>

namespace slipfront::app {

namespace {

constexpr const char* exit_codes = R"(exit codes:
  0    success
  1    the run failed (I/O or internal error)
  2    invalid job or command line (each error as "pointer: reason" on stderr)
  3    the run diverged (metrics still printed, no result file written)
  130  interrupted by SIGINT (no result file written)

The job JSON and the result file: docs/api-job-spec.md, docs/hdf5-layout.md.)";

struct Slipfront {
  CLI::App top{"slipfront: frictional interface rupture simulations (Kammer et al. 2014)",
               "slipfront"};
  std::map<const CLI::App*, std::function<int()>> commands;
  bool version = false;
  CLI::App* help = nullptr; // slipfront help [COMMAND]
  std::string help_topic;

  Slipfront() {
    top.formatter(std::make_shared<HelpFormat>());
    top.set_help_flag("-h,--help", "this help");
    top.allow_extras();
    top.add_flag("--version", version, "the code version (as results record it)");
    for (auto add : {add_run_command, add_validate_command, add_schema_command, add_presets_command,
                     add_stations_command, add_fit_length_command, add_serve_command,
                     add_check_command, add_calibrate_command}) {
      Command command = add(top);
      commands[command.cli] = std::move(command.run);
    }
    // `help` and `version` are spelled as commands too; they stay out of the list.
    help = top.add_subcommand("help", "the help of slipfront or of one command");
    help->add_option("COMMAND", help_topic, "a command");
    help->group("");
    top.add_subcommand("version", "the code version")->group("");
    top.footer(exit_codes);
    // One command per command line: in `slipfront help run` the word "run" is help's topic.
    top.require_subcommand(0, 1);
  }

  // The command that was given (nullptr: none).
  const CLI::App* given() const {
    const std::vector<CLI::App*> parsed = top.get_subcommands();
    return parsed.empty() ? nullptr : parsed.front();
  }

  // CLI::App::help() shows the help of the command given; this one shows `command`'s.
  static std::string help_of(const CLI::App& command) {
    return command.get_formatter()->make_help(&command, "", CLI::AppFormatMode::Normal);
  }

  int help_on(const std::string& topic) {
    if (topic.empty()) {
      std::cout << help_of(top);
      return exit_code::success;
    }
    for (const auto& [command, run] : commands)
      if (command->get_name() == topic) {
        std::cout << help_of(*command);
        return exit_code::success;
      }
    return unknown_command(topic);
  }

  int unknown_command(const std::string& name) {
    std::cerr << "slipfront: unknown command \"" << name << "\"\n\n" << help_of(top);
    return exit_code::bad_input;
  }

  int main(int argc, char** argv) {
    try {
      top.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
      const CLI::App* command = given();
      std::cout << help_of(command != nullptr ? *command : top);
      return exit_code::success;
    } catch (const CLI::ParseError& e) {
      const CLI::App* command = given();
      const CLI::App& where = command != nullptr ? *command : top;
      return command_line_error(where, parse_error_reason(where, e));
    }
    const CLI::App* command = given();
    if (command == nullptr) {
      if (version) return print_version();
      const std::vector<std::string> left = top.remaining();
      if (!left.empty() && !left.front().starts_with("-")) return unknown_command(left.front());
      if (!left.empty()) return command_line_error(top, unexpected_arguments(top));
      std::cerr << help_of(top);
      return exit_code::bad_input;
    }
    if (const std::string extra = unexpected_arguments(*command); !extra.empty())
      return command_line_error(*command, extra);
    if (command == help) return help_on(help_topic);
    if (command->get_name() == "version") return print_version();
    return commands.at(command)();
  }

  static int print_version() {
    std::cout << "slipfront " << slipfront::code_version() << '\n';
    return exit_code::success;
  }
};

} // namespace

} // namespace slipfront::app

int main(int argc, char** argv) {
  slipfront::app::Slipfront slipfront;
  return slipfront.main(argc, argv);
}
