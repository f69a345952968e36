#include "api/job_spec.hpp"

#include "api/job_checks.hpp"
#include "api/job_methods.hpp"
#include "api/job_reader.hpp"
#include "api/json_fields.hpp"
#include "api/json_parse.hpp"
#include "api/presets.hpp"
#include "api/result_estimate.hpp"
#include "api/run_bounds.hpp"
#include "api/scene_checks.hpp"
#include "api/scene_defaults.hpp"
#include "solver/simulation.hpp"

namespace slipfront::api {

ParseResult parse_job(const nlohmann::json& given, const ValidationLimits& limits) {
  ParseResult result;
  if (!given.is_object()) {
    result.errors.push_back({"", "the job must be a JSON object, got " + describe_value(given)});
    return result;
  }
  // {"preset": NAME, ...}: the preset's spec with the job's members merged over it.
  const nlohmann::json document = expand_preset(given, result.errors);
  if (!result.errors.empty()) return result;

  JobSpec job;
  ObjectReader reader(&document, "", result.errors);
  read_job_fields(reader, job);
  reader.finish();
  job.canonical = reader.canonical(); // the run bounds name fields in the form they were given
  // The defaults of the job's own scale (derived probes are then checked as given ones).
  if (result.errors.empty()) apply_scene_defaults(given, document, job);
  check_job_consistency(job, result.errors);
  if (!result.errors.empty()) return result;
  // The wave speeds, the time step and the step count before any estimate uses them.
  check_run_bounds(job, result.errors);
  if (!result.errors.empty()) return result;

  job.memory_estimate_bytes = estimated_memory_bytes(job.params);
  check_memory(job, limits, result.errors);
  job.result_estimate_bytes = estimated_result_bytes(job.params);
  check_result_size(job, limits, result.errors);
  if (!result.errors.empty()) return result;

  job.sha256 = spec_hash(job.canonical);
  job.warnings = scene_warnings(job);
  result.spec = std::move(job);
  return result;
}

ParseResult parse_job_text(const std::string& text, const ValidationLimits& limits) {
  auto document = parse_bounded_json(text);
  if (!document.ok()) {
    ParseResult result;
    result.errors.push_back(document.error);
    return result;
  }
  return parse_job(document.value, limits);
}

std::string canonical_text(const nlohmann::json& canonical) {
  return canonical.dump();
}

nlohmann::json physics_canonical(const nlohmann::json& canonical) {
  nlohmann::json physics = canonical;
  for (const char* key : {"name", "tags", "threads", "output"})
    physics.erase(key);
  // The default method ("fe") is the method every record had before the field existed:
  // leaving it out keeps FE hashes (the result cache, the studies' scenes) those of the older
  // records.
  if (method_name_of(physics) == default_method().method.name()) physics.erase("method");
  // A section of options at the value older records did not have ("fe": {"mesh_damping": 0},
  // the undamped scheme of every record before the section existed): left out for the same
  // reason (api/job_methods.hpp).
  for (const MethodOptions* options : method_options())
    if (const auto section = physics.find(options->section);
        section != physics.end() && !options->unhashed.is_null() && *section == options->unhashed)
      physics.erase(options->section);
  // "lower": {"solid": "rigid"} is the rigid plane of every record before the section existed.
  if (const auto lower = physics.find("lower");
      lower != physics.end() && *lower == nlohmann::json{{"solid", "rigid"}})
    physics.erase("lower");
  return physics;
}

std::string spec_hash(const nlohmann::json& canonical) {
  return sha256_hex(canonical_text(physics_canonical(canonical)));
}

// The scene of a study (docs/metrics.md "Critical length"): everything but L and n_d (and what
// never changes the metrics, as in spec_hash), and but the stations: where a run is watched
// does not change the scene.
std::string scene_hash(const nlohmann::json& canonical) {
  nlohmann::json scene = physics_canonical(canonical); // so the method separates scenes
  scene.erase("stations");
  if (scene.contains("friction") && scene["friction"].is_object()) scene["friction"].erase("L");
  if (scene.contains("geometry") && scene["geometry"].is_object())
    scene["geometry"].erase("nodes_per_meter");
  return sha256_hex(canonical_text(scene));
}

nlohmann::json counterpart_document(const nlohmann::json& job) {
  const MethodEntry* own = find_method(method_name_of(job));
  return method_document(job, method_entry((own != nullptr ? *own : default_method()).counterpart));
}

std::string counterpart_scene_hash(const nlohmann::json& canonical) {
  const ParseResult parsed = parse_job(counterpart_document(canonical));
  return parsed.ok() ? scene_hash(parsed.spec->canonical) : std::string();
}

} // namespace slipfront::api
