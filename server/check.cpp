#include "server/check.hpp"

#include "server/db/database.hpp"
#include "server/db/file_intents.hpp"
#include "server/db/malformed_rows.hpp"
#include "server/services/result_files.hpp"

#include <filesystem>
#include <iostream>

namespace slipfront::server {

int check_main(const std::string& data_dir) {
  const std::string path = data_dir + "/slipfront.db";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    std::cerr << "slipfront check: " << path
              << (std::filesystem::exists(path, ec) ? ": not a database file"
                                                    : ": No such file or directory")
              << '\n';
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
    // Result files no row refers to: left by an import or a delete a crash interrupted (the
    // next start removes them), or put there by hand.
    for (const auto& intent : read_file_intents(db)) {
      std::cout << "an interrupted " << intent.kind << " of " << intent.created_at << " ("
                << intent.paths.size() << " result file(s)): the next start finishes it\n";
      ++problems;
    }
    for (const auto& stray : find_stray_results(data_dir, read_result_references(db))) {
      std::cout << stray.path << ": no job refers to it"
                << (stray.temporary ? " (a temporary file of a run or import that did not finish)"
                                    : "")
                << "; the next start removes it\n";
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
