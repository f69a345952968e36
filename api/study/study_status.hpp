// The status of a study (docs/studies-api.md): running until every run it planned is final,
// then finished; cancelled when a client cancels it (its queued and running runs cancelled).
#pragma once

#include <optional>
#include <string_view>

namespace slipfront::api {

enum class StudyStatus { running, finished, cancelled };

// "running", "finished", "cancelled": the names of the API and of the database column.
inline const char* to_string(StudyStatus status) {
  switch (status) {
  case StudyStatus::running:
    return "running";
  case StudyStatus::finished:
    return "finished";
  case StudyStatus::cancelled:
    return "cancelled";
  }
  return "running";
}

// The status of a name; nullopt for any other text.
inline std::optional<StudyStatus> parse_study_status(std::string_view text) {
  for (auto s : {StudyStatus::running, StudyStatus::finished, StudyStatus::cancelled})
    if (text == to_string(s)) return s;
  return std::nullopt;
}

} // namespace slipfront::api
