// One analysis step of a study: from its runs (job statuses and metrics), the convergence
// status of every run, the convergence map, L_c with the spectral estimate, progress and
// the study's status. Pure (no I/O): StudySupervisor loads, calls this, stores.
#pragma once

#include "server/db/study_store.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace slipfront::server {

// Fills runs[i].convergence_status / partner_n_d / changes / reason and study.result,
// L_c, spectral_critical_length, runs_done, runs_total and status ("finished" when every
// run is final and `plans_open` is false). Runs are analysed per regime (one scene each).
// `refinement`: the plans of a convergence study per L (null for other kinds).
void analyse_study(StudyRecord& study, std::vector<StudyRunRow>& runs,
                   const nlohmann::json& refinement, bool plans_open, const std::string& now);

// The map and L_c of any set of runs of one scene (GET /convergence-map).
nlohmann::json scene_analysis(const std::vector<StudyRunRow>& runs);

// The cross-method table (api::cross_method_table) of one scene's runs by two methods (by
// name, in the registry's order: FE, then spectral_bi).
nlohmann::json cross_method(const std::string& first, const std::vector<StudyRunRow>& first_rows,
                            const std::string& second, const std::vector<StudyRunRow>& second_rows);

} // namespace slipfront::server
