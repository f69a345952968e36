#include "server/http/job_filter_query.hpp"

#include "server/core/run_query.hpp"

#include <charconv>
#include <cmath>
#include <set>
#include <sstream>

namespace slipfront::server {

std::optional<bool> parse_bool(const std::string& s) {
  if (s == "true" || s == "1" || s == "yes") return true;
  if (s == "false" || s == "0" || s == "no") return false;
  return std::nullopt;
}

std::optional<double> parse_finite_double(const std::string& s) {
  double v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

std::optional<long> parse_long(const std::string& s) {
  long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return v;
}

std::vector<std::string> split_commas(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  std::string item;
  while (std::getline(in, item, ','))
    if (!item.empty()) out.push_back(item);
  return out;
}

bool asks_for_export(const std::map<std::string, std::string>& query) {
  auto it = query.find("format");
  return it != query.end() && (it->second == "csv" || it->second == "ndjson");
}

JobFilterQuery parse_job_filter(const std::map<std::string, std::string>& q) {
  JobFilterQuery result;
  JobFilter& f = result.filter;
  std::vector<api::FieldError>& errors = result.errors;
  static const std::set<std::string> known = {
      "status",   "tag",     "name",    "outcome", "submitted_by", "spec_sha256", "L_min",
      "L_max",    "n_d_min", "n_d_max", "limit",   "cursor",       "fields",      "scene_hash",
      "study_id", "where",   "sort",    "format",  "archived"};
  for (const auto& [key, value] : q)
    if (!known.count(key)) errors.push_back({"/query/" + key, "unknown query parameter"});
  if (auto it = q.find("status"); it != q.end())
    for (const auto& s : split_commas(it->second)) {
      auto st = parse_status(s);
      if (st)
        f.statuses.push_back(*st);
      else
        errors.push_back({"/query/status", "unknown status " + s});
    }
  auto text = [&](const char* key, std::string& out) {
    if (auto it = q.find(key); it != q.end()) out = it->second;
  };
  text("tag", f.tag);
  text("name", f.name);
  text("outcome", f.outcome);
  text("submitted_by", f.submitted_by);
  text("spec_sha256", f.spec_sha256);
  text("scene_hash", f.scene_hash);
  text("study_id", f.study_id);
  // Archived runs are left out of listings and exports unless asked for.
  f.archived = ArchivedRuns::exclude;
  if (auto it = q.find("archived"); it != q.end()) {
    if (it->second == "include")
      f.archived = ArchivedRuns::include;
    else if (it->second == "only")
      f.archived = ArchivedRuns::only;
    else if (it->second != "exclude")
      errors.push_back(
          {"/query/archived", "must be exclude, include or only, got '" + it->second + "'"});
  }
  auto number = [&](const char* key, std::optional<double>& out) {
    if (auto it = q.find(key); it != q.end()) {
      out = parse_finite_double(it->second);
      if (!out) errors.push_back({std::string("/query/") + key, "must be a finite number"});
    }
  };
  number("L_min", f.L_min);
  number("L_max", f.L_max);
  number("n_d_min", f.n_d_min);
  number("n_d_max", f.n_d_max);
  std::string& format = result.format;
  if (auto it = q.find("format"); it != q.end()) {
    format = it->second;
    if (format != "json" && format != "csv" && format != "ndjson")
      errors.push_back({"/query/format", "must be json, csv or ndjson, got '" + format + "'"});
  }
  const bool table = asks_for_export(q);
  const long max_limit = table ? 100000 : 1000;
  if (table) f.limit = 10000;
  if (auto it = q.find("limit"); it != q.end()) {
    auto l = parse_long(it->second);
    if (!l || *l < 1 || *l > max_limit)
      errors.push_back({"/query/limit", "must be an integer in [1, " + std::to_string(max_limit) +
                                            "] for format=" + format});
    else
      f.limit = static_cast<int>(*l);
  }
  try {
    if (auto it = q.find("where"); it != q.end()) f.conditions = parse_where(it->second);
  } catch (const QueryError& e) {
    errors.push_back({"/query/" + e.parameter(), e.what()});
  }
  try {
    if (auto it = q.find("sort"); it != q.end()) f.sort = parse_sort(it->second);
  } catch (const QueryError& e) {
    errors.push_back({"/query/" + e.parameter(), e.what()});
  }
  if (auto it = q.find("cursor"); it != q.end()) {
    // Newest-first listings page by seq ("123"), sorted ones by offset ("o50").
    const std::string& text = it->second;
    const bool sorted = !f.sort.empty();
    auto c = parse_long(sorted && !text.empty() && text[0] == 'o' ? text.substr(1) : text);
    if (!c || *c < 0 || (sorted && text[0] != 'o') || (!sorted && text[0] == 'o'))
      errors.push_back({"/query/cursor", "must be a cursor returned as next_cursor by a listing "
                                         "with the same sort"});
    else if (sorted)
      f.offset = *c;
    else
      f.before_seq = *c;
  }
  if (auto it = q.find("fields"); it != q.end()) result.fields = split_commas(it->second);
  return result;
}

} // namespace slipfront::server
