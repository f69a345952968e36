// The run table of GET /api/v1/jobs?format=csv|ndjson: one flat row per job with its job
// columns, every spec field (`spec.friction.L`), every scalar metric (`metrics.outcome`,
// `metrics.rupture_speed.max`), the cost and the convergence status within its study.
#pragma once

#include "server/core/job.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace slipfront::server {

// One flat row; keys keep the order: job columns, spec.*, metrics.* (arrays left out).
nlohmann::ordered_json run_row(const Job& job, const std::string& convergence_status);

// The RFC 4180 CSV of run rows, built one row at a time: a header (the union of the rows'
// keys: the job columns in first-seen order, then spec.* and metrics.*, each sorted) and one
// line per row; empty cells for null or missing values; CRLF line ends. A row is kept as the
// text of its cells, about 1 kB, not as JSON (about 20 kB), until the header is known.
class RunTableCsv {
public:
  void add(const nlohmann::ordered_json& row);
  std::string text() const;

private:
  struct Row {
    std::string cells;                                     // the cells' text, one after another
    std::vector<std::pair<std::size_t, std::size_t>> ends; // (column, end of its cell in cells)
  };
  std::vector<std::string> columns_; // first-seen order
  std::map<std::string, std::size_t, std::less<>> column_index_;
  std::vector<Row> rows_;
};

} // namespace slipfront::server
