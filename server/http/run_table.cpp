#include "server/http/run_table.hpp"

#include "api/job_methods.hpp"
#include "api/json_number.hpp"
#include "server/http/api_prefix.hpp"

#include <algorithm>
#include <string_view>

namespace slipfront::server {

namespace {

void flatten(const nlohmann::json& j, const std::string& prefix, nlohmann::ordered_json& row) {
  // nlohmann::json objects iterate in sorted key order, so columns come out sorted.
  for (const auto& [key, value] : j.items()) {
    std::string name = prefix + "." + key;
    if (value.is_object())
      flatten(value, name, row);
    else if (!value.is_array())
      row[name] = value;
  }
}

nlohmann::json text_or_null(const std::string& s) {
  return s.empty() ? nlohmann::json(nullptr) : nlohmann::json(s);
}

// A text cell that a spreadsheet would read as a formula (=, +, -, @, or a tab or carriage
// return before one) starts with ' instead (OWASP, "CSV Injection"); numbers stay numbers.
std::string csv_cell(const nlohmann::ordered_json& v) {
  if (v.is_null()) return "";
  std::string text = v.is_string() ? v.get<std::string>() : v.dump();
  if (v.is_string() && !text.empty() &&
      std::string_view("=+-@\t\r").find(text[0]) != std::string_view::npos)
    text.insert(0, 1, '\'');
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}

} // namespace

nlohmann::ordered_json run_row(const Job& job, const std::string& convergence_status) {
  nlohmann::ordered_json row;
  row["id"] = job.id;
  row["name"] = job.name;
  row["status"] = to_string(job.status);
  row["method"] = api::method_name_of(job.spec);
  std::string tags;
  for (const auto& t : job.tags)
    tags += (tags.empty() ? "" : ";") + t;
  row["tags"] = tags;
  row["outcome"] = job.metrics.is_object() && job.metrics.contains("outcome")
                       ? job.metrics["outcome"]
                       : nlohmann::json(nullptr);
  row["convergence_status"] = text_or_null(convergence_status);
  row["study_id"] = text_or_null(job.study_id);
  row["submitted_by"] = text_or_null(job.submitted_by);
  row["created_at"] = text_or_null(job.created_at);
  row["finished_at"] = text_or_null(job.finished_at);
  row["wall_time_s"] =
      job.started_at.empty() ? nlohmann::json(nullptr) : api::json_number(job.wall_time_s);
  row["memory_estimate_bytes"] = api::json_bytes(job.memory_estimate_bytes);
  row["cached_from"] = text_or_null(job.cached_from);
  row["error"] = text_or_null(job.error);
  // Provenance, what a paper cites: the physics (spec_sha256), the scene (scene_hash), the
  // code that ran, and the result file with its checksum and its URL on this server.
  row["spec_sha256"] = text_or_null(job.spec_sha256);
  row["scene_hash"] = text_or_null(job.scene_hash);
  row["code_version"] = text_or_null(job.code_version);
  const bool has_result = job.status == JobStatus::succeeded && !job.result.path.empty();
  row["result_sha256"] = has_result ? text_or_null(job.result.sha256) : nlohmann::json(nullptr);
  row["result_size_bytes"] = has_result ? nlohmann::json(job.result.size) : nlohmann::json(nullptr);
  row["result_url"] = has_result ? nlohmann::json(api_prefix + "/jobs/" + job.id + "/result.h5")
                                 : nlohmann::json(nullptr);
  if (job.spec.is_object()) {
    nlohmann::json spec = job.spec;
    spec.erase("name");
    spec.erase("tags");
    flatten(spec, "spec", row);
  }
  if (job.metrics.is_object()) flatten(job.metrics, "metrics", row);
  api::whole_numbers_as_integers(row); // "spec.geometry.nodes_per_meter": 10, not 10.0
  return row;
}

void RunTableCsv::add(const nlohmann::ordered_json& row) {
  Row kept;
  for (const auto& [key, value] : row.items()) {
    auto [it, added] = column_index_.try_emplace(key, columns_.size());
    if (added) columns_.push_back(key);
    kept.cells += csv_cell(value);
    kept.ends.emplace_back(it->second, kept.cells.size());
  }
  rows_.push_back(std::move(kept));
}

std::string RunTableCsv::text() const {
  // Job columns first (in first-seen order), then spec.* and metrics.*, each sorted.
  auto group = [](const std::string& key) {
    return key.rfind("spec.", 0) == 0 ? 1 : key.rfind("metrics.", 0) == 0 ? 2 : 0;
  };
  std::vector<std::size_t> order(columns_.size()); // header position -> column
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    int ga = group(columns_[a]), gb = group(columns_[b]);
    if (ga != gb) return ga < gb;
    return ga != 0 && columns_[a] < columns_[b];
  });
  std::vector<std::size_t> position(columns_.size()); // column -> header position
  for (std::size_t i = 0; i < order.size(); ++i)
    position[order[i]] = i;

  std::string out;
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (i) out += ',';
    out += csv_cell(columns_[order[i]]);
  }
  out += "\r\n";
  std::vector<std::string_view> line(columns_.size());
  for (const auto& row : rows_) {
    std::fill(line.begin(), line.end(), std::string_view());
    std::size_t begin = 0;
    for (const auto& [column, end] : row.ends) {
      line[position[column]] = std::string_view(row.cells).substr(begin, end - begin);
      begin = end;
    }
    for (std::size_t i = 0; i < line.size(); ++i) {
      if (i) out += ',';
      out += line[i];
    }
    out += "\r\n";
  }
  return out;
}

} // namespace slipfront::server
