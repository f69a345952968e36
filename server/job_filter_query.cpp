#include "server/job_filter_query.hpp"

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

JobFilterQuery parse_job_filter(const std::map<std::string, std::string>& q) {
  JobFilterQuery result;
  JobFilter& f = result.filter;
  std::vector<api::FieldError>& errors = result.errors;
  static const std::set<std::string> known = {
      "status",  "tag",     "name",  "outcome", "submitted_by", "spec_sha256", "L_min",   "L_max",
      "n_d_min", "n_d_max", "limit", "cursor",  "fields",       "scene_hash",  "study_id"};
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
  if (auto it = q.find("limit"); it != q.end()) {
    auto l = parse_long(it->second);
    if (!l || *l < 1 || *l > 1000)
      errors.push_back({"/query/limit", "must be an integer in [1, 1000]"});
    else
      f.limit = static_cast<int>(*l);
  }
  if (auto it = q.find("cursor"); it != q.end()) {
    auto c = parse_long(it->second);
    if (!c || *c < 0)
      errors.push_back({"/query/cursor", "must be a cursor returned as next_cursor"});
    else
      f.before_seq = *c;
  }
  if (auto it = q.find("fields"); it != q.end()) result.fields = split_commas(it->second);
  return result;
}

} // namespace slipfront::server
