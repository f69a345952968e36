// A study as the API shows it: GET /api/v1/studies/{id} (the view, with its runs and the
// comparison with the other method) and each entry of GET /api/v1/studies (a summary).
#pragma once

#include "server/core/study.hpp"
#include "server/services/study_service.hpp"

#include <nlohmann/json.hpp>

#include <vector>

namespace slipfront::server {

// `summary` leaves out the runs and the analysis.
nlohmann::json study_to_json(const StudyRecord& study, const std::vector<StudyRunRow>& runs,
                             bool summary = false);

nlohmann::json study_to_json(const StudyView& view);

} // namespace slipfront::server
