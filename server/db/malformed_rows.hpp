// Rows whose stored JSON (a job's spec, tags, metrics or front; a study's request, base, tags
// or result) does not parse: found by SQLite's json_valid() without reading a row into the
// server's types. `slipfront check` lists them; the server logs them at start-up and skips them
// in listings (docs/reliability.md).
#pragma once

#include "server/db/database.hpp"

#include <string>
#include <vector>

namespace slipfront::server {

struct MalformedRow {
  std::string table; // "jobs", "metrics" or "studies"
  std::string id;    // the job's or study's id
  std::string column;
};

std::vector<MalformedRow> find_malformed_rows(Database& db);

// "jobs ID: spec is not JSON" for the log and the check command.
std::string describe(const MalformedRow& row);

} // namespace slipfront::server
