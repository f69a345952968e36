// What a run's (or a study's) owner may change after submission (PATCH /api/v1/jobs/{id} and
// PATCH /api/v1/studies/{id}, docs/server.md "Keep, annotate, share"): its tags and a free-text
// note. Neither is part of the physics.
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

// A change of tags: either every tag replaced (`replace`, "tags" in the body), or some added
// and some removed ("tags_add", "tags_remove"), the others kept.
struct TagChange {
  std::optional<std::vector<std::string>> replace;
  std::vector<std::string> add;
  std::vector<std::string> remove;
  bool empty() const { return !replace && add.empty() && remove.empty(); }
};

// The tags after `change`, or the error naming the field (/tags_add: too many tags). The
// kept tags keep their order, the added ones follow in the order given, each tag once;
// removing a tag the run does not have is no error.
struct TagsAfter {
  std::vector<std::string> tags;
  std::optional<FieldError> error;
};
TagsAfter apply_tag_change(const std::vector<std::string>& tags, const TagChange& change);

struct RunAnnotations {
  TagChange tags;
  std::optional<std::string> note; // given: the new note ("" clears it)
};

struct AnnotationsParse {
  RunAnnotations annotations;
  std::vector<FieldError> errors; // each names its field by JSON pointer (/tags/2, /note)
  bool ok() const { return errors.empty(); }
};

// Reads {"tags": [...], "note": "..."} or {"tags_add": [...], "tags_remove": [...],
// "note": "..."}: at least one member; "tags" (replace all) with "tags_add" or "tags_remove"
// is an error, as is a tag both added and removed; unknown fields are errors.
AnnotationsParse parse_annotations(const nlohmann::json& body);

} // namespace slipfront::api
