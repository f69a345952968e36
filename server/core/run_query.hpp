// The search language of GET /api/v1/jobs (docs/server.md, "Searching and exporting runs"): `where`
// conditions and `sort` keys over the run table, parsed into a small syntax tree whose fields
// come from a whitelist (job columns, every leaf of the canonical job spec, every metric).
// The SQL that answers it, with every value and JSON path a bound parameter, is the store's
// (server/db/run_query_sql.hpp).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace slipfront::server {

// A filter or sort that cannot be used: `parameter` is the query parameter ("where", "sort").
class QueryError : public std::runtime_error {
public:
  QueryError(std::string parameter, const std::string& reason)
      : std::runtime_error(reason), parameter_(std::move(parameter)) {}
  const std::string& parameter() const { return parameter_; }

private:
  std::string parameter_;
};

enum class FieldType { number, text, boolean, tag };

// Where a field is read: a job column, a leaf of the canonical spec, or a metric.
enum class FieldSource { job, spec, metrics };

// A whitelisted field.
struct RunField {
  std::string name; // as written by the user, normalised ("friction.L", "metrics.outcome")
  FieldSource source = FieldSource::job;
  std::string key; // the job column ("created_at"), spec path ("friction.L") or metric
                   // ("rupture_speed.max")
  FieldType type = FieldType::number;
};

enum class CompareOp { eq, ne, lt, le, gt, ge };

struct Condition {
  RunField field;
  CompareOp op = CompareOp::eq;
  std::variant<double, std::string> value; // a number (true/false: 1/0) or text
  // Text written without quotes that reads as a finite number. A text field kept as JSON may
  // hold numbers in some runs (geometry.height: "auto" or 20): there it compares as a number.
  std::optional<double> bare_number;
};

struct SortKey {
  RunField field;
  bool descending = false;
};

// Bounds on one search: each condition and key becomes SQL, and SQLite refuses an expression
// tree deeper than 1000 (docs/server.md, "Searching and exporting runs"). Above them: QueryError.
inline constexpr std::size_t max_where_conditions = 64;
inline constexpr std::size_t max_sort_keys = 16;

// Conditions joined by `;` or ` and `: `friction.L<1e-4; metrics.outcome=arrested`.
std::vector<Condition> parse_where(std::string_view text);
// A comma list of fields, each optionally prefixed by `-` (descending) or `+`.
std::vector<SortKey> parse_sort(std::string_view text);

// Resolves a field name against the whitelist; throws QueryError(parameter, ...) if unknown.
RunField resolve_field(std::string_view name, const std::string& parameter);

// The field names accepted (for error messages and the docs' test).
std::vector<std::string> searchable_fields();

} // namespace slipfront::server
