#include "server/core/run_query.hpp"

#include "api/job_spec.hpp"
#include "api/run_job.hpp"
#include "server/core/comma_list.hpp"
#include "solver/methods.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <mutex>

namespace slipfront::server {

namespace {

struct JobField {
  const char* name;
  FieldType type;
};

// The job columns. `method` of records made before the field existed is absent: FE.
const JobField job_fields[] = {
    {"id", FieldType::text},
    {"name", FieldType::text},
    {"status", FieldType::text},
    {"method", FieldType::text},
    {"outcome", FieldType::text},
    {"tag", FieldType::tag},
    {"tags", FieldType::tag}, // the run table's column name: tags=paper means tag=paper
    {"submitted_by", FieldType::text},
    {"created_at", FieldType::text},
    {"started_at", FieldType::text},
    {"finished_at", FieldType::text},
    {"study_id", FieldType::text},
    {"scene_hash", FieldType::text},
    {"spec_sha256", FieldType::text},
    {"code_version", FieldType::text},
    {"convergence_status", FieldType::text},
    {"wall_time_s", FieldType::number},
    {"memory_estimate_bytes", FieldType::number},
    {"attempts", FieldType::number},
    {"priority", FieldType::number},
    {"L", FieldType::number},
    {"n_d", FieldType::number},
};

FieldType type_of(const nlohmann::json& value) {
  if (value.is_string()) return FieldType::text;
  if (value.is_boolean()) return FieldType::boolean;
  return FieldType::number; // numbers, and metrics that are null in an empty run
}

// Every scalar leaf of `j` as "a.b.c" -> type (arrays are not searchable).
void collect_leaves(const nlohmann::json& j, const std::string& prefix,
                    std::map<std::string, FieldType>& out) {
  for (const auto& [key, value] : j.items()) {
    std::string path = prefix.empty() ? key : prefix + "." + key;
    if (value.is_object())
      collect_leaves(value, path, out);
    else if (!value.is_array())
      out.emplace(path, type_of(value));
  }
}

struct Whitelist {
  std::map<std::string, FieldType> spec;
  std::map<std::string, FieldType> metrics;
};

// The spec leaves of the canonical default job of every method, and the metrics of an
// empty run: new fields become searchable without touching this file.
const Whitelist& whitelist() {
  static const Whitelist w = [] {
    Whitelist out;
    for (const MethodEntry* entry : methods()) {
      const std::string method(entry->method.name());
      auto parsed = api::parse_job(nlohmann::json{{"method", method}});
      if (!parsed.ok())
        throw std::logic_error("the default job of method " + method +
                               " does not validate: " + parsed.errors.front().reason);
      collect_leaves(parsed.spec->canonical, "", out.spec);
    }
    out.spec.erase("name");
    collect_leaves(api::metrics_json(RunResult{}), "", out.metrics);
    return out;
  }();
  return w;
}

bool is_field_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
}

std::optional<double> parse_number(const std::string& text) {
  if (text.empty()) return std::nullopt;
  char* end = nullptr;
  double v = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

class WhereParser {
public:
  explicit WhereParser(std::string_view text) : s_(text) {}

  std::vector<Condition> parse() {
    std::vector<Condition> out;
    skip_spaces();
    if (at_end()) throw QueryError("where", "is empty: write e.g. where=friction.L<1e-4");
    while (true) {
      out.push_back(condition());
      skip_spaces();
      if (at_end()) break;
      if (s_[i_] == ';') {
        ++i_;
      } else if (at_keyword_and()) {
        i_ += 3;
      } else {
        fail("expected ';' or 'and' after condition " + std::to_string(out.size()));
      }
      skip_spaces();
      if (at_end()) fail("ends after a separator; a condition must follow");
    }
    return out;
  }

private:
  [[noreturn]] void fail(const std::string& reason) {
    throw QueryError("where", reason + " (at character " + std::to_string(i_ + 1) + ")");
  }
  bool at_end() const { return i_ >= s_.size(); }
  void skip_spaces() {
    while (!at_end() && std::isspace(static_cast<unsigned char>(s_[i_])))
      ++i_;
  }
  bool at_keyword_and() const {
    if (i_ + 3 > s_.size()) return false;
    auto word = s_.substr(i_, 3);
    bool is_and = std::equal(word.begin(), word.end(), "and", [](char a, char b) {
      return std::tolower(static_cast<unsigned char>(a)) == b;
    });
    return is_and && (i_ + 3 == s_.size() || std::isspace(static_cast<unsigned char>(s_[i_ + 3])));
  }

  Condition condition() {
    std::size_t start = i_;
    while (!at_end() && is_field_char(s_[i_]))
      ++i_;
    if (i_ == start) fail("expected a field name");
    std::string name(s_.substr(start, i_ - start));
    Condition c;
    c.field = resolve_field(name, "where");
    skip_spaces();
    c.op = op();
    skip_spaces();
    auto [text, quoted] = value();
    c.value = typed_value(c.field, c.op, text, quoted);
    if (c.field.type == FieldType::text && !quoted) c.bare_number = parse_number(text);
    return c;
  }

  CompareOp op() {
    auto rest = s_.substr(i_);
    static const std::pair<const char*, CompareOp> ops[] = {
        {"<=", CompareOp::le}, {">=", CompareOp::ge}, {"!=", CompareOp::ne}, {"==", CompareOp::eq},
        {"<", CompareOp::lt},  {">", CompareOp::gt},  {"=", CompareOp::eq}};
    for (const auto& [text, op] : ops)
      if (rest.substr(0, std::string_view(text).size()) == text) {
        i_ += std::string_view(text).size();
        return op;
      }
    fail("expected a comparison (=, !=, <, <=, >, >=)");
  }

  std::pair<std::string, bool> value() {
    if (at_end()) fail("expected a value");
    char q = s_[i_];
    if (q == '\'' || q == '"') {
      std::size_t close = s_.find(q, i_ + 1);
      if (close == std::string_view::npos) fail("unterminated quoted value");
      std::string text(s_.substr(i_ + 1, close - i_ - 1));
      i_ = close + 1;
      return {text, true};
    }
    std::size_t start = i_;
    while (!at_end() && s_[i_] != ';' && !std::isspace(static_cast<unsigned char>(s_[i_])))
      ++i_;
    if (i_ == start) fail("expected a value");
    return {std::string(s_.substr(start, i_ - start)), false};
  }

  std::variant<double, std::string> typed_value(const RunField& f, CompareOp op,
                                                const std::string& text, bool quoted) {
    switch (f.type) {
    case FieldType::number: {
      auto v = quoted ? std::nullopt : parse_number(text);
      if (!v) fail(f.name + " is a number; '" + text + "' is not a finite number");
      return *v;
    }
    case FieldType::boolean:
      if (text == "true") return 1.0;
      if (text == "false") return 0.0;
      fail(f.name + " is true or false, not '" + text + "'");
    case FieldType::tag:
      if (op != CompareOp::eq && op != CompareOp::ne)
        fail(f.name + " takes = or != only (whether a run has that tag)");
      return text;
    case FieldType::text:
      return text;
    }
    return text;
  }

  std::string_view s_;
  std::size_t i_ = 0;
};

} // namespace

RunField resolve_field(std::string_view name_view, const std::string& parameter) {
  std::string name(name_view);
  for (const auto& f : job_fields)
    if (name == f.name) return {name, FieldSource::job, name, f.type};
  const auto& w = whitelist();
  if (name.rfind("metrics.", 0) == 0) {
    std::string key = name.substr(8);
    if (auto it = w.metrics.find(key); it != w.metrics.end())
      return {name, FieldSource::metrics, key, it->second};
    throw QueryError(parameter, "unknown metric '" + key +
                                    "' (metrics are those of GET "
                                    "/api/v1/jobs/{id}/metrics, e.g. "
                                    "metrics.arrest_position)");
  }
  std::string path = name.rfind("spec.", 0) == 0 ? name.substr(5) : name;
  if (auto it = w.spec.find(path); it != w.spec.end())
    return {name, FieldSource::spec, path, it->second};
  throw QueryError(parameter, "unknown field '" + name +
                                  "' (a job column such as outcome or created_at, a spec "
                                  "field such as friction.L, or metrics.NAME)");
}

std::vector<std::string> searchable_fields() {
  std::vector<std::string> out;
  for (const auto& f : job_fields)
    out.push_back(f.name);
  for (const auto& [path, type] : whitelist().spec)
    out.push_back(path);
  for (const auto& [key, type] : whitelist().metrics)
    out.push_back("metrics." + key);
  return out;
}

std::vector<Condition> parse_where(std::string_view text) {
  auto conditions = WhereParser(text).parse();
  if (conditions.size() > max_where_conditions)
    throw QueryError("where", "has " + std::to_string(conditions.size()) + " conditions; at most " +
                                  std::to_string(max_where_conditions) + " conditions are allowed");
  return conditions;
}

std::vector<SortKey> parse_sort(std::string_view text) {
  std::vector<SortKey> out;
  const auto items = split_list(text);
  if (items.size() > max_sort_keys)
    throw QueryError("sort", "has " + std::to_string(items.size()) + " keys; at most " +
                                 std::to_string(max_sort_keys) + " keys are allowed");
  for (std::string_view item : items) {
    SortKey key;
    if (!item.empty() && (item.front() == '-' || item.front() == '+')) {
      key.descending = item.front() == '-';
      item.remove_prefix(1);
    }
    if (item.empty()) throw QueryError("sort", "has an empty key: write e.g. sort=-friction.L");
    if (!std::all_of(item.begin(), item.end(), is_field_char))
      throw QueryError("sort", "'" + std::string(item) + "' is not a field name");
    key.field = resolve_field(item, "sort");
    if (key.field.type == FieldType::tag)
      throw QueryError("sort", "cannot sort by " + key.field.name);
    out.push_back(std::move(key));
  }
  return out;
}

} // namespace slipfront::server
