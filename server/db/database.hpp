// Thin RAII wrappers over the SQLite C API: a connection and prepared statements, whose
// row values are read by column index or by result column name.
// Every failure throws SqliteError carrying SQLite's message and the SQL that failed.
#pragma once

#include "server/core/storage_error.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace slipfront::server {

// The kind of StorageError (server/core/storage_error.hpp) the store throws.
class SqliteError : public StorageError {
public:
  explicit SqliteError(const std::string& what, int code = 0)
      : StorageError(what, unavailable_code(code)), code_(code) {}
  int code() const { return code_; } // SQLite's (extended) result code; 0 if unknown
  // Disk full, I/O error, busy, locked, read-only, cannot open, out of memory, protocol:
  // the storage cannot take writes now (StorageError::unavailable()).
  static bool unavailable_code(int code);

private:
  int code_;
};

class Statement {
public:
  Statement(sqlite3* db, const std::string& sql);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;
  Statement(Statement&& other) noexcept;

  // Binding (1-based index). Empty optionals and NaN doubles bind NULL.
  Statement& bind(int index, const std::string& value);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, double value);
  Statement& bind_null(int index);
  Statement& bind(int index, const std::optional<std::string>& value);
  Statement& bind(int index, const std::optional<double>& value);

  bool step();  // true while a row is available
  void run();   // step to completion (for statements returning no rows)
  void reset(); // ready to run again; bindings cleared
  int changes() const;

  bool is_null(int column) const;
  std::string text(int column) const; // "" for NULL
  std::int64_t integer(int column) const;
  double real(int column) const; // NaN for NULL
  std::optional<double> optional_real(int column) const;

  // The same by result column name (the name after AS, else the column's own name);
  // throws SqliteError naming the SQL when the row has no such column.
  int column_index(const std::string& name) const;
  bool is_null(const std::string& name) const { return is_null(column_index(name)); }
  std::string text(const std::string& name) const { return text(column_index(name)); }
  std::int64_t integer(const std::string& name) const { return integer(column_index(name)); }
  double real(const std::string& name) const { return real(column_index(name)); }

private:
  void check(int rc, const char* what) const;
  sqlite3* db_ = nullptr;
  sqlite3_stmt* stmt_ = nullptr;
  std::string sql_;
  mutable std::vector<std::string> names_; // result column names, read on first use
};

class Database {
public:
  explicit Database(const std::string& path);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  void exec(const std::string& sql); // one or more statements, no rows
  Statement prepare(const std::string& sql) { return Statement(db_, sql); }
  std::int64_t user_version();
  std::int64_t last_insert_rowid();
  void set_user_version(std::int64_t version);
  std::string path() const { return path_; }
  sqlite3* handle() { return db_; }

private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

// BEGIN IMMEDIATE ... COMMIT; rolls back when destroyed without commit(). Inside a
// transaction already open on the connection it is a savepoint instead (RELEASE on commit(),
// ROLLBACK TO when destroyed without it), so that a store method that is one transaction can
// also be one step of a larger one (StoreDb::in_transaction).
class Transaction {
public:
  explicit Transaction(Database& db);
  ~Transaction();
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  void commit();

private:
  Database& db_;
  bool nested_ = false;
  bool done_ = false;
};

// A JSON column as read back: empty text is null; text that is not JSON throws with `what`
// (e.g. "spec of job 3f2a...") in the message.
nlohmann::json parse_stored_json(const std::string& text, const std::string& what);

} // namespace slipfront::server
