#include "server/services/study_progress.hpp"

#include "api/json_number.hpp"
#include "api/study/failure_regimes.hpp"
#include "server/core/job.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace slipfront::server {

using nlohmann::json;

namespace {

std::string outcome_of(const StudyRunRow& row) {
  if (row.metrics.is_object() && row.metrics.contains("outcome") &&
      row.metrics["outcome"].is_string())
    return row.metrics["outcome"].get<std::string>();
  return "";
}

// Convergence statuses of one regime's runs, written into the rows.
void assign_statuses(const std::vector<StudyRunRow*>& rows,
                     const std::vector<api::RunConvergence>& statuses) {
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& s = statuses[i];
    rows[i]->convergence_status = api::to_string(s.status);
    rows[i]->partner_n_d = s.partner_n_d;
    rows[i]->propagation_distance_change = s.propagation_distance_change;
    rows[i]->arrival_time_change = s.arrival_time_change;
    rows[i]->reason = s.reason;
  }
}

json group_json(const std::vector<StudyRunRow*>& rows, const std::vector<api::StudyRun>& runs) {
  json g;
  g["convergence_map"] = api::convergence_map(runs);
  g["critical_length"] = api::critical_length(runs);
  json outcomes = json::array();
  for (const auto* r : rows)
    outcomes.push_back({{"job_id", r->job_id},
                        {"L", r->L},
                        {"n_d", r->n_d},
                        {"job_status", r->job_status},
                        {"outcome", outcome_of(*r).empty() ? json(nullptr) : json(outcome_of(*r))},
                        {"convergence_status", r->convergence_status},
                        {"error", r->error.empty() ? json(nullptr) : json(r->error)}});
  g["runs"] = outcomes;
  g["scene_hash"] = rows.empty() ? json(nullptr) : json(rows.front()->scene_hash);
  return g;
}

} // namespace

void analyse_study(StudyRecord& study, std::vector<StudyRunRow>& rows, const json& refinement,
                   bool plans_open, const std::string& now) {
  std::map<std::string, std::vector<StudyRunRow*>> groups;
  for (auto& r : rows)
    groups[r.regime].push_back(&r);
  json result = json::object();
  json regimes = json::array();
  const std::string primary = study.kind == "failure_regimes" ? "regularised" : "";
  int done = 0;
  for (auto& [regime, members] : groups) {
    std::vector<api::StudyRun> runs;
    for (const auto* r : members)
      runs.push_back(to_study_run(*r));
    const auto statuses = api::convergence_statuses(runs);
    assign_statuses(members, statuses);
    json g = group_json(members, runs);
    if (regime == primary) {
      result["convergence_map"] = g["convergence_map"];
      result["critical_length"] = g["critical_length"];
    }
    if (!regime.empty()) {
      g["regime"] = regime;
      for (const auto& known : api::failure_regimes())
        if (known.name == regime) {
          g["description"] = known.description;
          g["expected"] = known.expected;
        }
      g["finding"] = api::regime_finding(runs, statuses);
      regimes.push_back(std::move(g));
    }
    for (const auto* r : members) {
      auto st = parse_status(r->job_status);
      if (st && is_final(*st)) ++done;
    }
  }
  if (!result.contains("convergence_map")) {
    result["convergence_map"] = api::convergence_map({});
    result["critical_length"] = api::critical_length({});
  }
  if (!regimes.empty()) result["regimes"] = regimes;
  if (!refinement.is_null()) result["refinement"] = refinement;
  study.result = result;
  study.L_c = result["critical_length"].value("L_c", json(nullptr)).is_number()
                  ? result["critical_length"]["L_c"].get<double>()
                  : api::not_available;
  const json& spectral = result["critical_length"]["spectral_critical_length"];
  study.spectral_critical_length =
      spectral.is_number() ? spectral.get<double>() : api::not_available;
  study.runs_done = done;
  study.runs_total = static_cast<int>(rows.size());
  study.updated_at = now;
  if (study.status == api::StudyStatus::cancelled) { // analysed as its runs end, never resumed
    if (done < study.runs_total)
      study.finished_at.clear();
    else if (study.finished_at.empty())
      study.finished_at = now; // its last run has ended
    return;
  }
  const bool finished = done == study.runs_total && !plans_open;
  if (finished && study.status != api::StudyStatus::finished) study.finished_at = now;
  study.status = finished ? api::StudyStatus::finished : api::StudyStatus::running;
  if (!finished) study.finished_at.clear();
}

json cross_method(const std::string& first, const std::vector<StudyRunRow>& first_rows,
                  const std::string& second, const std::vector<StudyRunRow>& second_rows) {
  std::vector<api::StudyRun> a, b;
  for (const auto& r : first_rows)
    a.push_back(to_study_run(r));
  for (const auto& r : second_rows)
    b.push_back(to_study_run(r));
  return api::cross_method_table({first, a}, {second, b});
}

json scene_analysis(const std::vector<StudyRunRow>& rows) {
  std::vector<api::StudyRun> runs;
  for (const auto& r : rows)
    runs.push_back(to_study_run(r));
  json out;
  out["convergence_map"] = api::convergence_map(runs);
  out["critical_length"] = api::critical_length(runs);
  auto statuses = api::convergence_statuses(runs);
  json list = json::array();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const std::string outcome = outcome_of(r);
    list.push_back(
        {{"job_id", r.job_id},
         {"L", r.L},
         {"n_d", r.n_d},
         {"job_status", r.job_status},
         {"outcome", outcome.empty() ? json(nullptr) : json(outcome)},
         {"submitted_by", r.submitted_by},
         {"study_id", r.study_id.empty() ? json(nullptr) : json(r.study_id)},
         {"convergence",
          {{"status", api::to_string(statuses[i].status)},
           {"partner_n_d", api::json_number(statuses[i].partner_n_d)},
           {"changes",
            {{"propagation_distance", api::json_number(statuses[i].propagation_distance_change)},
             {"arrival_time", api::json_number(statuses[i].arrival_time_change)}}},
           {"reason", statuses[i].reason}}}});
  }
  out["runs"] = list;
  out["count"] = rows.size();
  return out;
}

} // namespace slipfront::server
