// The `slipfront` executable: run, validate, schema, presets, stations, fit-length, serve, check
// (docs/api-job-spec.md "The CLI", docs/server.md; usage in app/usage.cpp).
#include "app/commands.hpp"

#include "server/check.hpp"
#include "server/serve.hpp"
#include "solver/simulation.hpp"

#include <iostream>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace slipfront::app;
  if (argc < 2) {
    print_usage(std::cerr);
    return exit_code::bad_input;
  }
  const std::string command = argv[1];
  const std::vector<std::string> args(argv + 2, argv + argc);

  if (command == "run") return run_command(args);
  if (command == "validate") return validate_command(args);
  if (command == "schema") return schema_command(args);
  if (command == "presets") return presets_command(args);
  if (command == "stations") return stations_command(args);
  if (command == "fit-length") return fit_length_command(args);
  if (command == "check") return slipfront::server::check_main(args);
  if (command == "serve") return slipfront::server::serve_main(argc - 2, argv + 2);
  if (command == "--version" || command == "version") {
    std::cout << "slipfront " << slipfront::code_version() << '\n';
    return exit_code::success;
  }
  if (command == "help" || command == "--help" || command == "-h") {
    print_usage(std::cout);
    return exit_code::success;
  }
  std::cerr << "slipfront: unknown command \"" << command << "\"\n\n";
  print_usage(std::cerr);
  return exit_code::bad_input;
}
