// `slipfront schema [--markdown]`: the job schema (api/job_schema.hpp), as JSON Schema or
// as the field tables of docs/api-job-spec.md.
#include "app/commands.hpp"
#include "app/options.hpp"

#include "api/job_schema.hpp"

#include <iostream>
#include <memory>

namespace slipfront::app {

Command add_schema_command(CLI::App& slipfront) {
  auto markdown = std::make_shared<bool>(false);
  CLI::App* command = add_command(
      slipfront, "schema",
      "The job schema: JSON Schema 2020-12 (also served at /api/v1/schema/job.json), every "
      "field with its type, range, default, unit and meaning; or the field tables of "
      "docs/api-job-spec.md.",
      "exit codes: 0 success, 2 invalid command line.");
  command->add_flag("--markdown", *markdown,
                    "the field tables (Markdown) instead of the JSON Schema");
  return {command, [markdown] {
            if (*markdown)
              std::cout << api::job_fields_markdown();
            else
              std::cout << api::job_json_schema().dump(2) << '\n';
            return exit_code::success;
          }};
}

} // namespace slipfront::app
