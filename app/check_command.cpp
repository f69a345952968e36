// `slipfront check DATA_DIR`: what a server could not read in DATA_DIR/slipfront.db, and
// the result files no job refers to (server/check.hpp; docs/server.md "Checking a data dir").
#include "app/commands.hpp"
#include "app/options.hpp"

#include "server/check.hpp"

#include <memory>

namespace slipfront::app {

Command add_check_command(CLI::App& slipfront) {
  auto data_dir = std::make_shared<std::string>();
  CLI::App* command = add_command(
      slipfront, "check",
      "List what a server could not read in DATA_DIR/slipfront.db (rows whose stored JSON "
      "does not parse, PRAGMA quick_check) and the files of DATA_DIR/results no job refers "
      "to; exit 0 and \"ok\" if nothing. Nothing is changed.",
      "exit codes: 0 nothing found, 1 problems found (or no database), 2 invalid command "
      "line.");
  command->add_option("DATA_DIR", *data_dir, "a server's --data-dir")->required();
  return {command, [data_dir] { return server::check_main(*data_dir); }};
}

} // namespace slipfront::app
