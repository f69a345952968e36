// The presets: named job templates a user starts from (docs/presets.md). The scene presets
// of presets/*.json (the field's standard scenes, with their source) and the job files of
// examples/, compiled into the program at build time (api/presets.cmake), so the CLI, the
// server and the web view offer the same list without a data directory.
//
// A job may name one: {"preset": "scec_tpv3_2d", "method": "spectral_bi"} is the preset's
// job for that method (preset_job) with the job's other members merged over it as a JSON
// merge patch (RFC 7396: objects merge member by member, anything else replaces, null
// removes). The stored spec is the
// expanded one, so a record never depends on the catalogue of the version that ran it.
#pragma once

#include "api/job_spec.hpp"

#include <nlohmann/json.hpp>

#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront::api {

struct Preset {
  std::string name;        // the file's stem: "scec_tpv3_2d", "quick_nd10"
  std::string origin;      // "presets" (a scene preset) or "examples" (a job file of examples/)
  std::string title;       // one line
  std::string description; // what the scene is and what it shows
  std::string reference;   // where its numbers come from ("" for the examples)
  nlohmann::json spec;     // the job for any method, as a user would write it
  // By a method's name, the members only that method reads ("fe": block heights, boundaries),
  // merged over `spec` when the job runs by it.
  std::map<std::string, nlohmann::json> own;
};

// Every preset: the scene presets first, then the examples, each group sorted by name.
const std::vector<Preset>& presets();

// The preset called `name`, or nullptr.
const Preset* find_preset(std::string_view name);

// The preset's job for `method` (a method's name: "fe", "spectral_bi"): `spec`, with "method"
// set for any but the default method and the method's own members merged over it.
nlohmann::json preset_job(const Preset& preset, const std::string& method);

// As a JSON object: {name, origin, title, description, reference, spec, specs}: `spec` the
// job by the preset's own method (FE unless its spec says), `specs` the job by each method.
nlohmann::json preset_json(const Preset& preset);

// The job with its "preset" member expanded (see above); the job unchanged when it names
// none. A "preset" that is not a string or names no preset is an error at "/preset", the
// known names in the reason; `errors` gets it and the job is returned unchanged.
nlohmann::json expand_preset(const nlohmann::json& job, std::vector<FieldError>& errors);

} // namespace slipfront::api
