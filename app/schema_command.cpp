// `slipfront schema [--markdown]`: the job schema (api/job_schema.hpp), as JSON Schema or
// as the field tables of docs/api-job-spec.md.
#include "app/commands.hpp"

#include "api/job_schema.hpp"

#include <iostream>

namespace slipfront::app {

int schema_command(const std::vector<std::string>& args) {
  bool markdown = false;
  for (const std::string& arg : args) {
    if (arg == "--markdown") {
      markdown = true;
    } else {
      std::cerr << "slipfront schema: unknown argument \"" << arg
                << "\" (usage: slipfront schema [--markdown])\n";
      return exit_code::bad_input;
    }
  }
  if (markdown) {
    std::cout << api::job_fields_markdown();
  } else {
    std::cout << api::job_json_schema().dump(2) << '\n';
  }
  return exit_code::success;
}

} // namespace slipfront::app
