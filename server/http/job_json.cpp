#include "server/http/job_json.hpp"

#include "api/job_methods.hpp"
#include "api/json_number.hpp"
#include "server/http/api_prefix.hpp"

namespace slipfront::server {

namespace {
nlohmann::json text_or_null(const std::string& value) {
  return value.empty() ? nlohmann::json(nullptr) : nlohmann::json(value);
}
} // namespace

nlohmann::json job_to_json(const Job& job, const std::vector<std::string>& fields) {
  nlohmann::json j;
  j["id"] = job.id;
  j["status"] = to_string(job.status);
  j["name"] = job.name;
  j["tags"] = job.tags;
  j["method"] = api::method_name_of(job.spec);
  j["spec"] = job.spec;
  j["spec_sha256"] = job.spec_sha256;
  j["submitted_by"] = text_or_null(job.submitted_by);
  j["priority"] = job.priority;
  j["created_at"] = text_or_null(job.created_at);
  j["started_at"] = text_or_null(job.started_at);
  j["finished_at"] = text_or_null(job.finished_at);
  j["progress"] = {{"fraction", job.progress.fraction},
                   {"time", job.progress.time},
                   {"duration", job.progress.duration},
                   {"steps", job.progress.steps},
                   {"eta_s", api::json_number(job.progress.eta_s)},
                   {"updated_at", text_or_null(job.progress.updated_at)}};
  j["metrics"] = job.metrics;
  j["error"] = text_or_null(job.error);
  j["wall_time_s"] =
      job.started_at.empty() ? nlohmann::json(nullptr) : api::json_number(job.wall_time_s);
  j["code_version"] = text_or_null(job.code_version);
  j["host"] = text_or_null(job.host);
  if (job.status == JobStatus::succeeded && !job.result.path.empty())
    j["result"] = {{"url", api_prefix + "/jobs/" + job.id + "/result.h5"},
                   {"size", job.result.size},
                   {"sha256", job.result.sha256}};
  else
    j["result"] = nullptr;
  j["cached_from"] = text_or_null(job.cached_from);
  j["memory_estimate_bytes"] = api::json_bytes(job.memory_estimate_bytes);
  j["attempts"] = job.attempts;
  j["scene_hash"] = text_or_null(job.scene_hash);
  j["study_id"] = text_or_null(job.study_id);
  j["executor"] = text_or_null(job.executor);
  j["slurm_job_id"] = text_or_null(job.slurm_job_id);
  j["slurm_state"] = text_or_null(job.slurm_state);
  j["note"] = job.note;
  j["archived_at"] = text_or_null(job.archived_at);
  j["imported_from"] = job.imported_from;
  // What the validation said when the job was accepted (null parts for older jobs).
  const auto validation = [&](const char* key, nlohmann::json absent) {
    return job.validation.is_object() && job.validation.contains(key) ? job.validation[key]
                                                                      : absent;
  };
  j["warnings"] = validation("warnings", nlohmann::json::array());
  j["provenance"] = validation("provenance", nullptr);
  j["estimate"] = validation("estimate", nullptr);
  j["resolution"] = validation("resolution", nullptr);
  j["links"] = {{"self", api_prefix + "/jobs/" + job.id},
                {"metrics", api_prefix + "/jobs/" + job.id + "/metrics"},
                {"front", api_prefix + "/jobs/" + job.id + "/front"},
                {"cancel", api_prefix + "/jobs/" + job.id + "/cancel"}};
  if (fields.empty()) return j;
  nlohmann::json projected;
  projected["id"] = job.id;
  for (const auto& field : fields)
    if (j.contains(field)) projected[field] = j[field];
  return projected;
}

} // namespace slipfront::server
