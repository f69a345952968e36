#include "server/db/store_db.hpp"

#include "server/db/migrations.hpp"

#include <filesystem>
#include <stdexcept>

namespace slipfront::server {

namespace {

// Before SQLite opens it: an empty file would be taken as a new, empty database.
const std::string& refuse_empty_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::exists(path, ec) && std::filesystem::file_size(path, ec) == 0 && !ec)
    throw std::runtime_error("database " + path +
                             " is an empty file (truncated?): refusing to start on it as on a "
                             "new database. Restore it from a backup (docs/server.md, Backups), "
                             "or delete it to start with an empty database");
  return path;
}

void check_integrity(Database& db) {
  std::string report;
  try {
    auto s = db.prepare("PRAGMA quick_check");
    while (s.step()) {
      if (!report.empty()) report += "; ";
      report += s.text(0);
      if (report.size() > 400) break;
    }
  } catch (const SqliteError& e) {
    report = e.what();
  }
  if (report != "ok")
    throw std::runtime_error("database " + db.path() +
                             " is damaged (PRAGMA quick_check: " + report +
                             "): refusing to start on it. Restore it from a backup "
                             "(docs/server.md, Backups); --integrity-check off starts anyway");
}

} // namespace

StoreDb::StoreDb(const std::string& path, bool integrity_check) : db_(refuse_empty_file(path)) {
  if (integrity_check) check_integrity(db_);
  db_.exec("PRAGMA busy_timeout = 5000");
  db_.exec("PRAGMA journal_mode = WAL");
  db_.exec("PRAGMA synchronous = FULL");
  migrate(db_); // with foreign keys off: a migration may rebuild a referenced table
  db_.exec("PRAGMA foreign_keys = ON");
  probe_db_.emplace(path);
  probe_db_->exec("PRAGMA busy_timeout = 1000");
}

StoreDb::~StoreDb() {
  {
    std::lock_guard readers(readers_mutex_);
    idle_readers_.clear(); // no read may run any more: the owner is going
  }
  std::lock_guard lock(mutex_);
  try {
    db_.exec("PRAGMA wal_checkpoint(TRUNCATE)");
  } catch (const std::exception&) { // the data is safe in the WAL; the next open replays it
  }
}

StoreDb::ReadConnection::ReadConnection(StoreDb& owner) : owner_(owner) {
  {
    std::lock_guard lock(owner_.readers_mutex_);
    if (!owner_.idle_readers_.empty()) {
      db_ = std::move(owner_.idle_readers_.back());
      owner_.idle_readers_.pop_back();
    }
  }
  if (!db_) {
    db_ = std::make_unique<Database>(owner_.db_.path());
    db_->exec("PRAGMA busy_timeout = 5000");
    db_->exec("PRAGMA query_only = ON");
  }
  db_->exec("BEGIN"); // one snapshot for every statement of the read
}

StoreDb::ReadConnection::~ReadConnection() {
  try {
    db_->exec("ROLLBACK"); // nothing was written: ends the read transaction
  } catch (const std::exception&) {
    return; // a connection in an unknown state is closed, not kept
  }
  std::lock_guard lock(owner_.readers_mutex_);
  owner_.idle_readers_.push_back(std::move(db_));
}

std::int64_t StoreDb::user_version() {
  std::lock_guard lock(probe_mutex_);
  return probe_db_->user_version();
}

} // namespace slipfront::server
