// The schema of the jobs database, versioned by PRAGMA user_version: migration i takes
// version i to i + 1. Each migration is a file of server/db/migrations/; a database is
// brought up to date at start-up (StoreDb), each step in one transaction.
#pragma once

#include "server/db/database.hpp"

#include <string>
#include <vector>

namespace slipfront::server {

struct Migration {
  std::string sql;
  // What SQL alone cannot do (recomputing values in C++), in the same transaction, after sql.
  void (*then)(Database&) = nullptr;
};

// In order: entry i takes user_version i to i + 1.
const std::vector<Migration>& schema_migrations();

// Runs the migrations `db` lacks (foreign keys must be off: a migration may rebuild a
// referenced table). Throws, naming the file and version, for a database newer than this
// build, a failed step, or a foreign key that no longer holds after one.
void migrate(Database& db);

// Part of migration 2 -> 3: jobs.scene_hash of every row that has none, recomputed from its
// stored canonical spec (api::scene_hash).
void fill_scene_hashes(Database& db);

} // namespace slipfront::server
