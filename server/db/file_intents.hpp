// What keeps the result files of the data dir and the rows of its database in step
// (docs/reliability.md "What bounds the disk"): the intents of changes that touch both (an
// import links files then inserts their rows, a delete removes a row then its file), and the
// result paths the rows refer to. Free functions on a connection, so that `slipfront check`
// reads them without the store (and without migrating an older database).
#pragma once

#include "server/db/database.hpp"

#include <cstdint>
#include <set>
#include <string>
#include <vector>

namespace slipfront::server {

struct FileIntent {
  std::int64_t id = 0;
  std::string kind;               // "import" or "delete"
  std::vector<std::string> paths; // result paths relative to the data dir
  std::string created_at;
};

// Inserts an intent (inside the caller's transaction, if any); returns its id.
std::int64_t insert_file_intent(Database& db, const std::string& kind,
                                const std::vector<std::string>& paths,
                                const std::string& created_at);
void delete_file_intent(Database& db, std::int64_t id);
// Every intent left (none when the table does not exist yet: an older database).
std::vector<FileIntent> read_file_intents(Database& db);

struct ResultReferences {
  std::set<std::string> paths;          // every result_path a job row holds
  std::set<std::string> unfinished_ids; // queued and running jobs: their file may appear
};
ResultReferences read_result_references(Database& db);

} // namespace slipfront::server
