// The one owner of the SQLite connection to the jobs database (slipfront.db in the data dir),
// shared by the job store and the study store: WAL mode, a busy timeout, the schema brought
// up to date at open (server/db/migrations.hpp), and a mutex so that HTTP handlers and
// workers take turns on the connection.
#pragma once

#include "server/db/database.hpp"

#include <cstdint>
#include <mutex>
#include <optional>
#include <string>

namespace slipfront::server {

class StoreDb {
public:
  // Refuses (throws) a zero-length database file and, unless `integrity_check` is false, a
  // database that fails PRAGMA quick_check: the server must not start on a damaged file.
  explicit StoreDb(const std::string& path, bool integrity_check = true);
  ~StoreDb(); // checkpoints the WAL into the database file
  StoreDb(const StoreDb&) = delete;
  StoreDb& operator=(const StoreDb&) = delete;

  // Runs `f(Database&)` holding the connection's lock. `f` should be one short transaction.
  template <class F> auto with_db(F&& f) {
    std::lock_guard lock(mutex_);
    return f(db_);
  }

  // Runs `f()` as one transaction, holding the connection's lock: the store calls f makes on
  // this thread join it (their own transactions become savepoints), so all of them are
  // committed together or none is. f returns true to commit, false to roll back (an exception
  // rolls back too). Returns what f returned.
  template <class F> bool in_transaction(F&& f) {
    std::lock_guard lock(mutex_);
    Transaction tx(db_);
    if (!f()) return false;
    tx.commit();
    return true;
  }

  // The connection, locked while the returned object lives: for a method that is one short
  // transaction (`auto db = store.lock(); db->prepare(...)`).
  class Locked {
  public:
    explicit Locked(StoreDb& owner) : lock_(owner.mutex_), db_(owner.db_) {}
    Database* operator->() { return &db_; }
    Database& operator*() { return db_; }

  private:
    std::lock_guard<std::recursive_mutex> lock_;
    Database& db_;
  };
  Locked lock() { return Locked(*this); }

  // On a connection of its own (the health check's): never waits behind a long listing
  // holding the lock.
  std::int64_t user_version();

  std::string path() const { return db_.path(); }

private:
  // Recursive: a thread inside in_transaction() calls store methods that take it again.
  std::recursive_mutex mutex_;
  Database db_;
  std::mutex probe_mutex_;
  std::optional<Database> probe_db_; // opened after the migrations
};

} // namespace slipfront::server
