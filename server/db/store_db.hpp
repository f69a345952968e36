// The one owner of the SQLite connections to the jobs database (slipfront.db in the data
// dir), shared by the job store and the study store: WAL mode, a busy timeout, the schema
// brought up to date at open (server/db/migrations.hpp), and a mutex so that HTTP handlers
// and workers take turns on the connection that writes. Long reads (listings, exports) run
// on read-only connections of their own: in WAL mode a reader sees the last commit and
// neither waits for the writer nor holds it up (docs/reliability.md).
#pragma once

#include "server/db/database.hpp"

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

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

  // Runs `f(Database&)` in one read transaction (one snapshot of the last commit) on a
  // read-only connection that no other thread uses meanwhile: an idle one, or a new one (as
  // many are opened as threads read at once, and kept). For reads over many rows: the
  // connection that writes stays free for submissions and workers.
  template <class F> auto read(F&& f) {
    ReadConnection connection(*this);
    return f(*connection);
  }

  // On a connection of its own (the health check's): never waits behind a long listing
  // holding the lock.
  std::int64_t user_version();

  std::string path() const { return db_.path(); }

private:
  // A read-only connection taken from idle_readers_ (or opened) and given back when done.
  class ReadConnection {
  public:
    explicit ReadConnection(StoreDb& owner);
    ~ReadConnection();
    ReadConnection(const ReadConnection&) = delete;
    ReadConnection& operator=(const ReadConnection&) = delete;
    Database& operator*() { return *db_; }

  private:
    StoreDb& owner_;
    std::unique_ptr<Database> db_;
  };

  // Recursive: a thread inside in_transaction() calls store methods that take it again.
  std::recursive_mutex mutex_;
  Database db_;
  std::mutex probe_mutex_;
  std::optional<Database> probe_db_; // opened after the migrations
  std::mutex readers_mutex_;
  std::vector<std::unique_ptr<Database>> idle_readers_;
};

} // namespace slipfront::server
