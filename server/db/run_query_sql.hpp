// The SQL of a job listing (server/core/job_filter.hpp) and of the search language's syntax
// tree (server/core/run_query.hpp): each field read from its column (the indexed ones) or from
// the stored JSON, every value and JSON path a numbered parameter, never spliced text.
#pragma once

#include "server/core/job_filter.hpp"
#include "server/core/run_query.hpp"
#include "server/db/database.hpp"

#include <string>
#include <variant>
#include <vector>

namespace slipfront::server {

// SQL with numbered parameters: `?N` placeholders appended in order.
struct SqlParams {
  std::vector<std::variant<double, std::string>> values;
  std::string add(std::variant<double, std::string> value); // returns "?N"
};

std::string condition_sql(const Condition& c, SqlParams& params);
std::string sort_sql(const SortKey& key, SqlParams& params);

// The SELECT of JobStore::list(filter), one row more than the page (a next page exists when
// it comes back), and its parameters: for EXPLAIN QUERY PLAN in tests.
struct ListQuery {
  std::string sql;
  SqlParams params;
};
ListQuery list_query(const JobFilter& filter);
void bind_all(Statement& statement, const SqlParams& params); // ?1, ?2, ... in order

} // namespace slipfront::server
