#include "server/check.hpp"

#include "server/db/database.hpp"
#include "server/db/malformed_rows.hpp"

#include <filesystem>
#include <iostream>

namespace slipfront::server {

int check_main(const std::vector<std::string>& args) {
  if (args.size() != 1 || args[0] == "--help" || args[0].empty() || args[0][0] == '-') {
    std::cerr << "usage: slipfront check DATA_DIR\n"
                 "  Lists the rows of DATA_DIR/slipfront.db a server cannot read (stored JSON\n"
                 "  that does not parse) and what PRAGMA quick_check finds; exit 0 if none.\n";
    return args.size() == 1 && args[0] == "--help" ? 0 : 2;
  }
  const std::string path = args[0] + "/slipfront.db";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::cerr << "slipfront check: " << path << " is not a database file\n";
    return 1;
  }
  try {
    Database db(path);
    int problems = 0;
    auto quick = db.prepare("PRAGMA quick_check");
    while (quick.step())
      if (quick.text(0) != "ok") {
        std::cout << "quick_check: " << quick.text(0) << '\n';
        ++problems;
      }
    for (const auto& row : find_malformed_rows(db)) {
      std::cout << describe(row) << '\n';
      ++problems;
    }
    if (problems == 0) {
      std::cout << "ok\n";
      return 0;
    }
    std::cout << problems << " problem(s) in " << path << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "slipfront check: " << path << ": " << e.what() << '\n';
    return 1;
  }
}

} // namespace slipfront::server
