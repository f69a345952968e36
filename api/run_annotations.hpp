// What a run's owner may change after submission (PATCH /api/v1/jobs/{id}, docs/server.md
// "Keep, annotate, share"): its tags and a free-text note. Neither is part of the physics.
#pragma once

#include "api/job_spec.hpp" // FieldError

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace slipfront::api {

// The bounds of a job's tags, at submission and after.
constexpr std::size_t max_tags = 32;
constexpr std::size_t max_tag_length = 64; // bytes
// The bounds of a run's note: lines of free text (api/free_text.hpp; newlines and tabs allowed).
constexpr std::size_t max_note_length = 4096; // bytes

struct RunAnnotations {
  std::optional<std::vector<std::string>> tags; // given: the new tags (replace the old ones)
  std::optional<std::string> note;              // given: the new note ("" clears it)
};

struct AnnotationsParse {
  RunAnnotations annotations;
  std::vector<FieldError> errors; // each names its field by JSON pointer (/tags/2, /note)
  bool ok() const { return errors.empty(); }
};

// Reads {"tags": [...], "note": "..."}: at least one of the two; unknown fields are errors.
AnnotationsParse parse_annotations(const nlohmann::json& body);

} // namespace slipfront::api
