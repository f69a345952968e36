#include "server/http/study_json.hpp"

#include "api/friction_fields.hpp"
#include "api/job_methods.hpp"
#include "api/job_spec.hpp"
#include "api/json_number.hpp"
#include "api/study/study_answer.hpp"
#include "server/core/study_request.hpp"
#include "server/http/api_prefix.hpp"

#include <map>

namespace slipfront::server {

using nlohmann::json;

namespace {

// Whether a study's scene is the paper's: the scene hash of an empty job of its method.
bool paper_scene(const std::string& method, const std::string& scene_hash) {
  static const std::map<std::string, std::string> paper = [] {
    std::map<std::string, std::string> hashes;
    for (const std::string& name : api::method_names()) {
      auto parsed = api::parse_job({{"method", name}});
      if (parsed.ok()) hashes[name] = api::scene_hash(parsed.spec->canonical);
    }
    return hashes;
  }();
  const auto found = paper.find(method);
  return found != paper.end() && found->second == scene_hash;
}

} // namespace

json study_to_json(const StudyRecord& s, const std::vector<StudyRunRow>& runs, bool summary) {
  const std::string self = api_prefix + "/studies/" + s.id;
  json j;
  j["id"] = s.id;
  j["name"] = s.name;
  j["tags"] = s.tags;
  j["kind"] = s.kind;
  j["status"] = api::to_string(s.status);
  j["submitted_by"] = s.submitted_by;
  j["created_at"] = s.created_at;
  j["updated_at"] = s.updated_at.empty() ? json(nullptr) : json(s.updated_at);
  j["finished_at"] = s.finished_at.empty() ? json(nullptr) : json(s.finished_at);
  j["scene_hash"] = s.scene_hash;
  j["method"] = api::method_name_of(s.base);
  j["companion_label"] = companion_label(s.base);
  j["progress"] = {{"done", s.runs_done},
                   {"total", s.runs_total},
                   {"fraction", s.runs_total ? double(s.runs_done) / s.runs_total : 0.0}};
  j["L_c"] = api::json_number(s.L_c);
  j["spectral_critical_length"] = api::json_number(s.spectral_critical_length);
  j["note"] = s.note;
  j["archived_at"] = s.archived_at.empty() ? json(nullptr) : json(s.archived_at);
  j["links"] = {{"self", self},
                {"speed_accuracy", self + "/speed-accuracy"},
                {"convergence_map", api_prefix + "/convergence-map?scene=" + s.scene_hash},
                {"jobs", api_prefix + "/jobs?study_id=" + s.id}};
  if (summary) return j;
  j["request"] = s.request;
  json list = json::array();
  for (const auto& r : runs) {
    std::string outcome;
    if (r.metrics.is_object() && r.metrics.contains("outcome") && r.metrics["outcome"].is_string())
      outcome = r.metrics["outcome"].get<std::string>();
    json run = {{"job_id", r.job_id},
                {"L", r.L},
                {"n_d", r.n_d},
                {"job_status", r.job_status},
                {"outcome", outcome.empty() ? json(nullptr) : json(outcome)},
                {"cached_from", r.cached_from.empty() ? json(nullptr) : json(r.cached_from)},
                {"error", r.error.empty() ? json(nullptr) : json(r.error)},
                {"convergence",
                 {{"status", r.convergence_status},
                  {"partner_n_d", api::json_number(r.partner_n_d)},
                  {"changes",
                   {{"propagation_distance", api::json_number(r.propagation_distance_change)},
                    {"arrival_time", api::json_number(r.arrival_time_change)}}},
                  {"reason", r.reason}}},
                {"links", {{"job", api_prefix + "/jobs/" + r.job_id}}}};
    if (!r.regime.empty()) run["regime"] = r.regime;
    list.push_back(std::move(run));
  }
  j["runs"] = list;
  const json& result = s.result.is_object() ? s.result : json::object();
  j["critical_length"] = result.value("critical_length", json(nullptr));
  j["convergence_map"] = result.value("convergence_map", json(nullptr));
  if (result.contains("refinement")) j["refinement"] = result["refinement"];
  if (result.contains("search")) j["search"] = result["search"];
  if (result.contains("accuracy")) j["accuracy"] = result["accuracy"];
  if (result.contains("regimes")) j["regimes"] = result["regimes"];
  // The headline answer first on every page that shows a study (docs/studies.md "The answer").
  j["answer"] = api::study_answer(j, paper_scene(j["method"].get<std::string>(), s.scene_hash));
  return j;
}

json study_to_json(const StudyView& view) {
  json j = study_to_json(view.study, view.runs);
  if (view.counterpart_scene_hash) {
    j["counterpart_scene_hash"] =
        view.counterpart_scene_hash->empty() ? json(nullptr) : json(*view.counterpart_scene_hash);
    if (view.cross_method) j["cross_method"] = *view.cross_method;
  }
  return j;
}

} // namespace slipfront::server
