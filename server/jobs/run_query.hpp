// The search language of GET /api/v1/jobs (docs/server.md, "Searching runs"): `where`
// conditions and `sort` keys over the run table, parsed into a small AST whose fields come
// from a whitelist (job columns, every leaf of the canonical job spec, every metric) and
// turned into SQL whose values (and JSON paths) are bound parameters, never spliced text.
#pragma once

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

// A whitelisted field: the SQL expression that reads it. When `json_path` is set the
// expression is `json_extract(<json_column>, ?)` with the path bound as a parameter.
struct RunField {
  std::string name;      // as written by the user, normalised ("friction.L", "metrics.outcome")
  std::string column;    // SQL column or expression (a constant of this file)
  std::string json_path; // "$.friction.L"; empty for plain columns
  FieldType type = FieldType::number;
};

enum class CompareOp { eq, ne, lt, le, gt, ge };

struct Condition {
  RunField field;
  CompareOp op = CompareOp::eq;
  std::variant<double, std::string> value;
};

struct SortKey {
  RunField field;
  bool descending = false;
};

// Conditions joined by `;` or ` and `: `friction.L<1e-4; metrics.outcome=arrested`.
std::vector<Condition> parse_where(std::string_view text);
// A comma list of fields, each optionally prefixed by `-` (descending) or `+`.
std::vector<SortKey> parse_sort(std::string_view text);

// Resolves a field name against the whitelist; throws QueryError(parameter, ...) if unknown.
RunField resolve_field(std::string_view name, const std::string& parameter);

// The field names accepted (for error messages and the docs' test).
std::vector<std::string> searchable_fields();

// SQL with numbered parameters: `?N` placeholders appended in order.
struct SqlParams {
  std::vector<std::variant<double, std::string>> values;
  std::string add(std::variant<double, std::string> value); // returns "?N"
};

std::string condition_sql(const Condition& c, SqlParams& params);
std::string sort_sql(const SortKey& key, SqlParams& params);

} // namespace slipfront::server
