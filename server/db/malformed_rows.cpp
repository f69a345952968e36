#include "server/db/malformed_rows.hpp"

namespace slipfront::server {

std::vector<MalformedRow> find_malformed_rows(Database& db) {
  struct Column {
    const char* table;
    const char* id;
    const char* column;
  };
  static constexpr Column columns[] = {
      {"jobs", "id", "spec"},
      {"jobs", "id", "tags"},
      {"metrics", "job_id", "metrics_json"},
      {"metrics", "job_id", "front_json"},
      {"studies", "id", "tags"},
      {"studies", "id", "base_spec"},
      {"studies", "id", "request"},
      {"studies", "id", "result"},
  };
  std::vector<MalformedRow> rows;
  for (const auto& c : columns) {
    auto s = db.prepare(std::string("SELECT ") + c.id + " FROM " + c.table + " WHERE " + c.column +
                        " IS NOT NULL AND " + c.column + " <> '' AND NOT json_valid(" + c.column +
                        ") ORDER BY " + c.id);
    while (s.step())
      rows.push_back({c.table, s.text(0), c.column});
  }
  return rows;
}

std::string describe(const MalformedRow& row) {
  return row.table + " " + row.id + ": " + row.column + " is not JSON";
}

} // namespace slipfront::server
