#include "server/db/job_rows.hpp"

#include <functional>
#include <optional>
#include <stdexcept>
#include <vector>

namespace slipfront::server {

namespace {

// Every column of jobs, in table order.
const std::vector<std::string>& job_columns() {
  static const std::vector<std::string> columns = {"seq",
                                                   "id",
                                                   "status",
                                                   "name",
                                                   "tags",
                                                   "spec",
                                                   "spec_sha256",
                                                   "submitted_by",
                                                   "idempotency_key",
                                                   "priority",
                                                   "fresh",
                                                   "L",
                                                   "n_d",
                                                   "memory_estimate_bytes",
                                                   "created_at",
                                                   "started_at",
                                                   "finished_at",
                                                   "progress_fraction",
                                                   "progress_time",
                                                   "progress_duration",
                                                   "progress_steps",
                                                   "progress_eta_s",
                                                   "progress_updated_at",
                                                   "error",
                                                   "wall_time_s",
                                                   "code_version",
                                                   "host",
                                                   "result_path",
                                                   "result_size",
                                                   "result_sha256",
                                                   "cached_from",
                                                   "attempts",
                                                   "scene_hash",
                                                   "study_id",
                                                   "executor",
                                                   "slurm_job_id",
                                                   "slurm_state",
                                                   "note",
                                                   "archived_at",
                                                   "imported_from",
                                                   "result_imported_by",
                                                   "validation"};
  return columns;
}

std::optional<std::string> text_or_null(const std::string& v) {
  return v.empty() ? std::nullopt : std::optional<std::string>(v);
}

// The columns a new job sets, each with the binding of its value.
using Binder = std::function<void(Statement&, int, const Job&)>;
const std::vector<std::pair<std::string, Binder>>& new_job_columns() {
  auto text = [](std::string Job::*member) {
    return [member](Statement& s, int i, const Job& j) { s.bind(i, j.*member); };
  };
  auto optional_text = [](std::string Job::*member) {
    return [member](Statement& s, int i, const Job& j) { s.bind(i, text_or_null(j.*member)); };
  };
  auto real = [](double Job::*member) {
    return [member](Statement& s, int i, const Job& j) { s.bind(i, j.*member); };
  };
  static const std::vector<std::pair<std::string, Binder>> columns = {
      {"id", text(&Job::id)},
      {"status",
       [](Statement& s, int i, const Job& j) { s.bind(i, std::string(to_string(j.status))); }},
      {"name", text(&Job::name)},
      {"tags", [](Statement& s, int i, const Job& j) { s.bind(i, nlohmann::json(j.tags).dump()); }},
      {"spec", [](Statement& s, int i, const Job& j) { s.bind(i, j.spec.dump()); }},
      {"spec_sha256", text(&Job::spec_sha256)},
      {"submitted_by", text(&Job::submitted_by)},
      {"idempotency_key", optional_text(&Job::idempotency_key)},
      {"priority", [](Statement& s, int i, const Job& j) { s.bind(i, std::int64_t{j.priority}); }},
      {"fresh",
       [](Statement& s, int i, const Job& j) { s.bind(i, std::int64_t{j.fresh ? 1 : 0}); }},
      {"L", real(&Job::L)},
      {"n_d", real(&Job::n_d)},
      {"memory_estimate_bytes", real(&Job::memory_estimate_bytes)},
      {"created_at", text(&Job::created_at)},
      {"started_at", optional_text(&Job::started_at)},
      {"finished_at", optional_text(&Job::finished_at)},
      {"progress_fraction",
       [](Statement& s, int i, const Job& j) { s.bind(i, j.progress.fraction); }},
      {"progress_time", [](Statement& s, int i, const Job& j) { s.bind(i, j.progress.time); }},
      {"progress_duration",
       [](Statement& s, int i, const Job& j) { s.bind(i, j.progress.duration); }},
      {"progress_steps", [](Statement& s, int i, const Job& j) { s.bind(i, j.progress.steps); }},
      {"progress_updated_at",
       [](Statement& s, int i, const Job& j) { s.bind(i, text_or_null(j.progress.updated_at)); }},
      {"error", optional_text(&Job::error)},
      {"wall_time_s", real(&Job::wall_time_s)},
      {"code_version", optional_text(&Job::code_version)},
      {"host", optional_text(&Job::host)},
      {"result_path",
       [](Statement& s, int i, const Job& j) { s.bind(i, text_or_null(j.result.path)); }},
      {"result_size", [](Statement& s, int i,
                         const Job& j) { s.bind(i, static_cast<std::int64_t>(j.result.size)); }},
      {"result_sha256",
       [](Statement& s, int i, const Job& j) { s.bind(i, text_or_null(j.result.sha256)); }},
      {"cached_from", optional_text(&Job::cached_from)},
      {"scene_hash", optional_text(&Job::scene_hash)},
      {"study_id", optional_text(&Job::study_id)},
      {"note", text(&Job::note)},
      {"archived_at", optional_text(&Job::archived_at)},
      {"result_imported_by", optional_text(&Job::result_imported_by)},
      {"imported_from",
       [](Statement& s, int i, const Job& j) {
         s.bind(i, j.imported_from.is_null() ? std::nullopt
                                             : std::optional<std::string>(j.imported_from.dump()));
       }},
      {"validation",
       [](Statement& s, int i, const Job& j) {
         s.bind(i, j.validation.is_null() ? std::nullopt
                                          : std::optional<std::string>(j.validation.dump()));
       }},
  };
  return columns;
}

} // namespace

const std::string& select_jobs() {
  static const std::string sql = [] {
    std::string s = "SELECT ";
    for (const auto& c : job_columns()) {
      s += "j.";
      s += c;
      s += " AS ";
      s += c;
      s += ", ";
    }
    s += "m.metrics_json AS metrics_json FROM jobs j LEFT JOIN metrics m ON m.job_id = j.id ";
    return s;
  }();
  return sql;
}

Job read_job(const Statement& s) {
  Job job;
  job.seq = s.integer("seq");
  job.id = s.text("id");
  auto status = parse_status(s.text("status"));
  if (!status)
    throw std::runtime_error("job " + job.id + " has unknown status " + s.text("status"));
  job.status = *status;
  job.name = s.text("name");
  job.tags =
      parse_stored_json(s.text("tags"), "tags of job " + job.id).get<std::vector<std::string>>();
  job.spec = parse_stored_json(s.text("spec"), "spec of job " + job.id);
  job.spec_sha256 = s.text("spec_sha256");
  job.submitted_by = s.text("submitted_by");
  job.idempotency_key = s.text("idempotency_key");
  job.priority = static_cast<int>(s.integer("priority"));
  job.fresh = s.integer("fresh") != 0;
  job.L = s.real("L");
  job.n_d = s.real("n_d");
  job.memory_estimate_bytes = s.real("memory_estimate_bytes");
  job.created_at = s.text("created_at");
  job.started_at = s.text("started_at");
  job.finished_at = s.text("finished_at");
  job.progress.fraction = s.real("progress_fraction");
  job.progress.time = s.real("progress_time");
  job.progress.duration = s.real("progress_duration");
  job.progress.steps = s.integer("progress_steps");
  job.progress.eta_s = s.real("progress_eta_s");
  job.progress.updated_at = s.text("progress_updated_at");
  job.error = s.text("error");
  job.wall_time_s = s.real("wall_time_s");
  job.code_version = s.text("code_version");
  job.host = s.text("host");
  job.result.path = s.text("result_path");
  job.result.size = static_cast<std::uint64_t>(s.integer("result_size"));
  job.result.sha256 = s.text("result_sha256");
  job.cached_from = s.text("cached_from");
  job.attempts = static_cast<int>(s.integer("attempts"));
  job.metrics = parse_stored_json(s.text("metrics_json"), "metrics of job " + job.id);
  job.scene_hash = s.text("scene_hash");
  job.study_id = s.text("study_id");
  job.executor = s.text("executor");
  job.slurm_job_id = s.text("slurm_job_id");
  job.slurm_state = s.text("slurm_state");
  job.note = s.text("note");
  job.archived_at = s.text("archived_at");
  job.imported_from = parse_stored_json(s.text("imported_from"), "provenance of job " + job.id);
  job.result_imported_by = s.text("result_imported_by");
  job.validation = parse_stored_json(s.text("validation"), "validation of job " + job.id);
  return job;
}

std::optional<Job> read_job_or_skip(const Statement& s, std::vector<std::string>& skipped) {
  try {
    return read_job(s);
  } catch (const std::exception& e) {
    skipped.push_back(s.text("id") + ": " + e.what());
    return std::nullopt;
  }
}

const std::string& insert_job_sql() {
  static const std::string sql = [] {
    std::string names, values;
    int i = 0;
    for (const auto& column : new_job_columns()) {
      if (i++) {
        names += ", ";
        values += ", ";
      }
      names += column.first;
      values += '?';
      values += std::to_string(i);
    }
    std::string s = "INSERT INTO jobs (";
    s += names;
    s += ") VALUES (";
    s += values;
    s += ")";
    return s;
  }();
  return sql;
}

void bind_new_job(Statement& insert, const Job& job) {
  int i = 0;
  for (const auto& column : new_job_columns())
    column.second(insert, ++i, job);
}

const std::string& metrics_columns() {
  static const std::string columns =
      "L, n_d, arrest_position, propagation_distance, arrival_time_at_probe, max_rupture_speed, "
      "mean_rupture_speed, max_slip_velocity, outcome, energy_error, wall_time_s, steps, dt, "
      "metrics_json, front_json";
  return columns;
}

} // namespace slipfront::server
