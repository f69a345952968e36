#include "server/db/database.hpp"

#include <sqlite3.h>

#include <cmath>
#include <limits>

namespace slipfront::server {

namespace {
// At most the first 200 characters of a statement, for an error (never tens of kB of SQL in
// the log).
std::string sql_excerpt(const std::string& sql) {
  constexpr std::size_t shown = 200;
  std::string out = "`";
  out.append(sql, 0, shown);
  if (sql.size() <= shown) return out + "`";
  out += "...` (";
  out += std::to_string(sql.size());
  out += " characters)";
  return out;
}

std::string message(sqlite3* db, int rc, const std::string& what) {
  std::string text = what + ": " + sqlite3_errstr(rc);
  if (db) text += " (" + std::string(sqlite3_errmsg(db)) + ")";
  return text;
}
} // namespace

bool SqliteError::unavailable_code(int code) {
  switch (code & 0xff) { // the primary code of an extended one
  case SQLITE_FULL:
  case SQLITE_IOERR:
  case SQLITE_BUSY:
  case SQLITE_LOCKED:
  case SQLITE_READONLY:
  case SQLITE_CANTOPEN:
  case SQLITE_NOMEM:
  case SQLITE_PROTOCOL:
    return true;
  default:
    return false;
  }
}

Statement::Statement(sqlite3* db, const std::string& sql) : db_(db), sql_(sql) {
  int rc = sqlite3_prepare_v2(db_, sql.c_str(), static_cast<int>(sql.size()), &stmt_, nullptr);
  if (rc != SQLITE_OK) throw SqliteError(message(db_, rc, "preparing SQL " + sql_excerpt(sql)), rc);
}

Statement::~Statement() {
  if (stmt_) sqlite3_finalize(stmt_);
}

Statement::Statement(Statement&& other) noexcept
    : db_(other.db_), stmt_(other.stmt_), sql_(std::move(other.sql_)) {
  other.stmt_ = nullptr;
}

void Statement::check(int rc, const char* what) const {
  if (rc != SQLITE_OK)
    throw SqliteError(message(db_, rc, std::string(what) + " " + sql_excerpt(sql_)), rc);
}

Statement& Statement::bind(int index, const std::string& value) {
  check(sqlite3_bind_text(stmt_, index, value.data(), static_cast<int>(value.size()),
                          SQLITE_TRANSIENT),
        "binding text in");
  return *this;
}

Statement& Statement::bind(int index, std::int64_t value) {
  check(sqlite3_bind_int64(stmt_, index, value), "binding integer in");
  return *this;
}

Statement& Statement::bind(int index, double value) {
  if (!std::isfinite(value)) return bind_null(index);
  check(sqlite3_bind_double(stmt_, index, value), "binding real in");
  return *this;
}

Statement& Statement::bind_null(int index) {
  check(sqlite3_bind_null(stmt_, index), "binding NULL in");
  return *this;
}

Statement& Statement::bind(int index, const std::optional<std::string>& value) {
  return value ? bind(index, *value) : bind_null(index);
}

Statement& Statement::bind(int index, const std::optional<double>& value) {
  return value ? bind(index, *value) : bind_null(index);
}

bool Statement::step() {
  int rc = sqlite3_step(stmt_);
  if (rc == SQLITE_ROW) return true;
  if (rc == SQLITE_DONE) return false;
  throw SqliteError(message(db_, rc, "running " + sql_excerpt(sql_)), rc);
}

void Statement::run() {
  while (step()) {
  }
}

void Statement::reset() {
  sqlite3_reset(stmt_);
  sqlite3_clear_bindings(stmt_);
}

int Statement::changes() const {
  return sqlite3_changes(db_);
}

bool Statement::is_null(int column) const {
  return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

std::string Statement::text(int column) const {
  const unsigned char* p = sqlite3_column_text(stmt_, column);
  if (!p) return {};
  return std::string(reinterpret_cast<const char*>(p),
                     static_cast<std::size_t>(sqlite3_column_bytes(stmt_, column)));
}

std::int64_t Statement::integer(int column) const {
  return sqlite3_column_int64(stmt_, column);
}

double Statement::real(int column) const {
  if (is_null(column)) return std::numeric_limits<double>::quiet_NaN();
  return sqlite3_column_double(stmt_, column);
}

std::optional<double> Statement::optional_real(int column) const {
  if (is_null(column)) return std::nullopt;
  return sqlite3_column_double(stmt_, column);
}

int Statement::column_index(const std::string& name) const {
  if (names_.empty()) {
    const int n = sqlite3_column_count(stmt_);
    for (int i = 0; i < n; ++i) {
      const char* column = sqlite3_column_name(stmt_, i);
      names_.emplace_back(column ? column : "");
    }
  }
  for (std::size_t i = 0; i < names_.size(); ++i)
    if (names_[i] == name) return static_cast<int>(i);
  throw SqliteError("no result column " + name + " in " + sql_excerpt(sql_));
}

Database::Database(const std::string& path) : path_(path) {
  int rc =
      sqlite3_open_v2(path.c_str(), &db_,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX, nullptr);
  if (rc != SQLITE_OK) {
    std::string text = message(db_, rc, "opening database " + path);
    sqlite3_close(db_);
    db_ = nullptr;
    throw SqliteError(text, rc);
  }
  sqlite3_extended_result_codes(db_, 1);
}

Database::~Database() {
  if (db_) sqlite3_close_v2(db_);
}

void Database::exec(const std::string& sql) {
  char* error = nullptr;
  int rc = sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error);
  if (rc != SQLITE_OK) {
    std::string text = "running " + sql_excerpt(sql) + ": " + (error ? error : sqlite3_errstr(rc));
    sqlite3_free(error);
    throw SqliteError(text, rc);
  }
}

std::int64_t Database::user_version() {
  Statement s(db_, "PRAGMA user_version");
  s.step();
  return s.integer(0);
}

std::int64_t Database::last_insert_rowid() {
  return sqlite3_last_insert_rowid(db_);
}

void Database::set_user_version(std::int64_t version) {
  exec("PRAGMA user_version = " + std::to_string(version));
}

Transaction::Transaction(Database& db)
    : db_(db), nested_(sqlite3_get_autocommit(db.handle()) == 0) {
  db_.exec(nested_ ? "SAVEPOINT nested" : "BEGIN IMMEDIATE");
}

Transaction::~Transaction() {
  if (!done_) {
    try {
      db_.exec(nested_ ? "ROLLBACK TO nested; RELEASE nested" : "ROLLBACK");
    } catch (...) { // a destructor cannot throw; the failure of the original operation is
                    // already propagating and carries the context
    }
  }
}

void Transaction::commit() {
  db_.exec(nested_ ? "RELEASE nested" : "COMMIT");
  done_ = true;
}

nlohmann::json parse_stored_json(const std::string& text, const std::string& what) {
  if (text.empty()) return nullptr;
  try {
    return nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw std::runtime_error("stored " + what + " is not JSON: " + e.what());
  }
}

} // namespace slipfront::server
