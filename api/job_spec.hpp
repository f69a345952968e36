// The job JSON (docs/api-job-spec.md): parsing, validation, defaults and canonical form.
//
// Every field is optional and defaults to the paper's scene. Unknown fields, wrong types
// and out-of-range values are errors; all errors of a spec are reported together, each
// with the JSON pointer of the offending field and the reason.
#pragma once

#include "solver/params.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::api {

struct FieldError {
  std::string pointer; // JSON pointer, e.g. "/material/poisson_ratio" ("" = the whole document)
  std::string reason;  // e.g. "must be in (0, 0.5), got 0.5"
};

// A remark on a valid job (api/scene_checks.hpp): a value the run will take that is likely not
// what the scene needs. Shown beside the field it names; it never refuses the job.
struct FieldWarning {
  std::string pointer; // JSON pointer of the field to look at
  std::string message;
};

// A value with a unit that the run takes, and where it came from (api/scene_defaults.hpp):
// "given", "preset NAME", "default" (the paper's scene) or "derived: how".
struct ValueSource {
  std::string pointer;
  double value = 0.0;
  std::string unit;
  std::string source;
};

struct ValidationLimits {
  double max_memory_bytes = 8.0e9; // a job whose memory estimate exceeds this is refused
  // A job whose result-file estimate exceeds this is refused (api/result_estimate.hpp).
  double max_result_bytes = std::numeric_limits<double>::infinity();
};

struct JobSpec {
  SimulationParams params;
  std::string name;              // free text, not part of the physics
  std::vector<std::string> tags; // free text, not part of the physics
  nlohmann::json canonical;      // every field present (defaults filled); keys sorted on dump
  std::string sha256;            // SHA-256 (hex) of the canonical physics: see spec_hash()
  double memory_estimate_bytes = 0.0;
  double result_estimate_bytes = 0.0;  // upper bound, uncompressed
  std::vector<FieldWarning> warnings;  // api/scene_checks.hpp
  std::vector<ValueSource> provenance; // every number with a unit, and its source
};

// {pointer, message} and {pointer, value, unit, source} as JSON arrays (the validation answer,
// the job record, the metrics and the result file hold them in this form).
nlohmann::json warnings_json(const std::vector<FieldWarning>& warnings);
nlohmann::json provenance_json(const std::vector<ValueSource>& provenance);

struct ParseResult {
  std::optional<JobSpec> spec; // set when errors is empty
  std::vector<FieldError> errors;
  bool ok() const { return errors.empty(); }
};

// Validate a parsed JSON document and build the job. A "preset" member is expanded first
// (api/presets.hpp): the job is the preset's spec with the other members merged over it.
ParseResult parse_job(const nlohmann::json& document, const ValidationLimits& limits = {});

// Parse text first (a syntax error is one FieldError with pointer "" and the parser's
// message); then as above.
ParseResult parse_job_text(const std::string& text, const ValidationLimits& limits = {});

// The canonical text: canonical JSON dumped with sorted keys and no whitespace.
std::string canonical_text(const nlohmann::json& canonical);

// The canonical spec without what does not change the metrics (`name`, `tags`, `threads`,
// `output`; `stations` is in it when the job has stations, since they add their rupture times
// to the metrics, and left out of the canonical form when it has none) and without the
// defaults that older records did not have (the default `"method": "fe"`, a method's section
// at its unhashed value — the undamped `"fe"` section, api/job_methods.hpp — and
// `"lower": {"solid": "rigid"}`), so that their hashes stay those of the records made before
// these fields existed.
nlohmann::json physics_canonical(const nlohmann::json& canonical);

// SHA-256 (lower-case hex) of the canonical text of physics_canonical(canonical).
std::string spec_hash(const nlohmann::json& canonical);

// SHA-256 of the canonical spec without friction.L, geometry.nodes_per_meter, stations, output,
// name, tags and threads: runs with the same scene hash belong to one convergence map.
std::string scene_hash(const nlohmann::json& canonical);

// The same physics by the job's counterpart method (its entry's `counterpart`: FE and the
// spectral BI method are each other's): method_document of api/job_methods.hpp, the fields
// only the job's method reads dropped (from FE: geometry.height, geometry.top_boundary,
// lower.height, lower.bottom_boundary, time.safety_factor and the "fe" section; from BI: the
// "spectral_bi" section). Not checked: parse it.
nlohmann::json counterpart_document(const nlohmann::json& job);
// The scene hash of counterpart_document(canonical); empty if that job is not valid.
std::string counterpart_scene_hash(const nlohmann::json& canonical);

// SHA-256 of arbitrary bytes / of a file's content (lower-case hex).
std::string sha256_hex(std::string_view bytes);
std::string sha256_file(const std::string& path);
// Of what is left to read from an open descriptor (to its end).
std::string sha256_descriptor(int fd);

} // namespace slipfront::api
