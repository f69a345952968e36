// The job schema (api/job_schema.hpp) against the reader it is recorded from: every field
// has its words, every range the schema states is the one validation enforces, and every
// choice it lists is accepted.
#include "api/job_schema.hpp"
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

namespace slipfront::api {
namespace {

// A field of the items of an array of objects is "/profiles/*/mu": in a job, item 0.
std::string job_pointer(const JobField& field) {
  std::string pointer = field.pointer;
  if (const auto star = pointer.find("/*/"); star != std::string::npos)
    pointer.replace(star, 3, "/0/");
  return pointer;
}

// The schema's x-when of a field as a list of conditions ({pointer, values}), one of which
// must hold; a field of `profiles` entries has the x-when of the friction field it overrides.
std::vector<nlohmann::json> conditions_of(const std::string& pointer) {
  static const nlohmann::json schema = job_json_schema();
  std::string own = pointer;
  if (own.starts_with("/profiles/*/")) own = "/friction/" + own.substr(12);
  const std::size_t slash = own.rfind('/');
  const std::string section = slash == 0 ? "" : own.substr(1, slash - 1);
  const nlohmann::json& parent = section.empty() ? schema : schema["properties"][section];
  if (!parent.is_object() || !parent.contains("properties")) return {};
  const nlohmann::json field =
      parent["properties"].value(own.substr(slash + 1), nlohmann::json::object());
  const nlohmann::json when = field.value("x-when", nlohmann::json());
  if (when.is_null()) return {};
  if (when.is_array()) return {when.begin(), when.end()};
  return {when};
}

// Makes the job choose what the field at `pointer` needs (its first x-when condition, and
// what that choice needs in turn: regularization needs a law that lets the job choose it).
void choose_for(nlohmann::json& job, const std::string& pointer, int depth = 0) {
  const std::vector<nlohmann::json> when = conditions_of(pointer);
  if (when.empty() || depth > 4) return;
  const std::string chooser = when.front()["pointer"];
  job[nlohmann::json::json_pointer(chooser)] = when.front()["values"][0];
  choose_for(job, chooser, depth + 1);
}

// The job in which a field applies: some fields belong to a choice made elsewhere (another
// friction law or regularisation, a type of nucleation, an elastic lower solid: the schema's
// x-when says which, derived from the laws) and are refused without it (docs/api-job-spec.md);
// the wave-speed form of the material is the other form; the options of `stations` are shown
// with one station.
nlohmann::json context_for(const JobField& field) {
  nlohmann::json job = nlohmann::json::object();
  const std::string& p = field.pointer;
  const std::string name = p.substr(p.rfind('/') + 1);
  choose_for(job, p);
  if (p == "/geometry/pml_elements") job["geometry"]["top_boundary"] = "pml";
  if (name == "p_wave_speed" || name == "s_wave_speed") { // of `material` or `lower`
    const Material paper;                                 // the default material in its other form
    const std::string section = p.substr(1, p.rfind('/') - 1);
    job[section]["p_wave_speed"] = paper.p_wave_speed();
    job[section]["s_wave_speed"] = paper.s_wave_speed();
  }
  if (p.starts_with("/stations/")) job["stations"]["x1"] = {0.0};
  // An entry that sets a shear stress far outside the domain: valid whatever the field.
  if (p.starts_with("/profiles/*/"))
    job["profiles"] = {{{"x1_min", 1e6}, {"x1_max", 2e6}, {"shear_stress", 0.0}}};
  return job;
}

// A job with `value` at the field, in its context, and the method the field belongs to.
nlohmann::json job_with(const JobField& field, const nlohmann::json& value) {
  nlohmann::json job = context_for(field);
  if (!field.read_by("fe")) job["method"] = "spectral_bi";
  job[nlohmann::json::json_pointer(job_pointer(field))] = value;
  return job;
}

bool has_error_at(const ParseResult& result, const std::string& pointer) {
  return std::any_of(result.errors.begin(), result.errors.end(),
                     [&](const FieldError& e) { return e.pointer == pointer; });
}

// Fields with no default: the other form of a material, and the values of a `profiles`
// entry (each is optional, an entry sets what it gives).
bool without_default(const std::string& pointer) {
  return pointer == "/material/p_wave_speed" || pointer == "/material/s_wave_speed" ||
         pointer == "/lower/p_wave_speed" || pointer == "/lower/s_wave_speed" ||
         (pointer.starts_with("/profiles/*/") && pointer != "/profiles/*/outside");
}

// Fields that stay out of the canonical form at their default, so that the jobs written
// before they existed keep their hash (docs/api-job-spec.md "Canonical form").
bool kept_out_at_default(const std::string& pointer) {
  return pointer == "/friction/regularization" || pointer == "/nucleation/type" ||
         pointer == "/profiles";
}

TEST(JobSchema, EveryFieldHasAUnitAndMeaningAndNoWordsAreLeftOver) {
  std::set<std::string> fields, documented;
  for (const JobField& f : job_fields()) {
    fields.insert(f.pointer);
    EXPECT_FALSE(f.meaning.empty()) << f.pointer;
    EXPECT_TRUE(f.schema.contains("default") || without_default(f.pointer)) << f.pointer;
    EXPECT_TRUE(f.read_by("fe") || f.read_by("spectral_bi")) << f.pointer;
  }
  for (const std::string& p : documented_job_pointers())
    documented.insert(p);
  EXPECT_EQ(fields, documented);
  EXPECT_GE(fields.size(), 37u); // the job of docs/api-job-spec.md and the two method sections
}

TEST(JobSchema, MethodSpecificFieldsAreMarked) {
  std::set<std::string> fe_only, bi_only;
  for (const JobField& f : job_fields()) {
    if (!f.read_by("spectral_bi")) fe_only.insert(f.pointer);
    if (!f.read_by("fe")) bi_only.insert(f.pointer);
  }
  EXPECT_EQ(fe_only,
            (std::set<std::string>{"/fe/mesh_damping", "/geometry/height", "/geometry/pml_elements",
                                   "/geometry/top_boundary", "/lower/bottom_boundary",
                                   "/lower/height", "/time/safety_factor"}));
  EXPECT_EQ(bi_only,
            (std::set<std::string>{"/spectral_bi/corrector_passes", "/spectral_bi/memory_periods",
                                   "/spectral_bi/time_step_factor"}));
}

// The default the schema states is what a job without the field gets (in the field's
// context, see context_for).
TEST(JobSchema, DefaultsAreTheCanonicalValuesOfAnEmptyJob) {
  // Without stations, "stations" stays out of the canonical form (so that the specs written
  // before it existed keep their hashes); its other defaults are those of a job with one.
  const ParseResult fe = parse_job(nlohmann::json::object());
  const ParseResult bi = parse_job({{"method", "spectral_bi"}});
  ASSERT_TRUE(fe.errors.empty() && bi.errors.empty());
  EXPECT_FALSE(fe.spec->canonical.contains("stations"));
  EXPECT_FALSE(bi.spec->canonical.contains("stations"));
  int compared = 0;
  for (const JobField& f : job_fields()) {
    if (f.pointer == "/stations/x1") {
      EXPECT_EQ(f.schema["default"], nlohmann::json::array());
      continue;
    }
    if (without_default(f.pointer)) {
      EXPECT_FALSE(f.schema.contains("default")) << f.pointer;
      continue;
    }
    nlohmann::json job = context_for(f);
    if (!f.read_by("fe")) job["method"] = "spectral_bi";
    const ParseResult parsed = parse_job(job);
    ASSERT_TRUE(parsed.errors.empty())
        << f.pointer << ": " << parsed.errors[0].pointer << " " << parsed.errors[0].reason;
    const nlohmann::json::json_pointer at(job_pointer(f));
    if (kept_out_at_default(f.pointer)) {
      EXPECT_FALSE(parsed.spec->canonical.contains(at)) << f.pointer;
      continue;
    }
    ASSERT_TRUE(parsed.spec->canonical.contains(at)) << f.pointer;
    EXPECT_EQ(parsed.spec->canonical.at(at), f.schema["default"]) << f.pointer;
    ++compared;
  }
  EXPECT_GE(compared, 37);
}

// Each bound of every number and integer field: the value on the bound is accepted when the
// bound is closed and refused (with an error at the field) when it is open, and a value
// beyond it is refused. One closed bound is narrowed by a rule across fields
// (api/job_checks.cpp), as its meaning says: space_stride <= the interface nodes (1600 here).
TEST(JobSchema, RangesAreTheOnesValidationEnforces) {
  int bounds = 0;
  for (const JobField& f : job_fields()) {
    const nlohmann::json& s = f.schema;
    if (!s.contains("type") || (s["type"] != "number" && s["type"] != "integer")) continue;
    const bool integer = s["type"] == "integer";
    auto check = [&](const char* key, double sign, bool open) {
      if (!s.contains(key)) return;
      const double bound = s[key].get<double>();
      const double beyond = integer ? bound + sign : bound + sign * (std::abs(bound) * 1e-6 + 1e-9);
      EXPECT_TRUE(has_error_at(parse_job(job_with(f, beyond)), job_pointer(f)))
          << f.pointer << " = " << beyond << " should be refused (" << key << " " << bound << ")";
      const bool narrowed = f.pointer == "/output/space_stride" && std::string(key) == "maximum";
      EXPECT_EQ(has_error_at(parse_job(job_with(f, bound)), job_pointer(f)), open || narrowed)
          << f.pointer << " = " << bound << " (" << key << ")";
      ++bounds;
    };
    check("minimum", -1.0, false);
    check("exclusiveMinimum", -1.0, true);
    check("maximum", +1.0, false);
    check("exclusiveMaximum", +1.0, true);
  }
  EXPECT_GE(bounds, 25);
}

TEST(JobSchema, EveryListedChoiceIsAcceptedAndOthersAreNot) {
  int choices = 0;
  for (const JobField& f : job_fields()) {
    if (!f.schema.contains("enum")) continue;
    for (const auto& name : f.schema["enum"]) {
      nlohmann::json job = job_with(f, name);
      if (f.pointer == "/method") job = {{"method", name}};
      EXPECT_FALSE(has_error_at(parse_job(job), f.pointer)) << f.pointer << " = " << name;
      ++choices;
    }
    EXPECT_TRUE(has_error_at(parse_job(job_with(f, "no-such-choice")), f.pointer)) << f.pointer;
  }
  EXPECT_GE(choices, 9);
}

TEST(JobSchema, JsonSchemaNestsTheSectionsAndClosesEveryObject) {
  const nlohmann::json schema = job_json_schema();
  EXPECT_EQ(schema["type"], "object");
  EXPECT_EQ(schema["additionalProperties"], false);
  const nlohmann::json& L = schema["properties"]["friction"]["properties"]["L"];
  EXPECT_EQ(L["type"], "number");
  EXPECT_EQ(L["exclusiveMinimum"], 0.0);
  EXPECT_EQ(L["default"], 5e-5);
  EXPECT_EQ(L["x-unit"], "m");
  EXPECT_EQ(schema["properties"]["friction"]["additionalProperties"], false);
  EXPECT_EQ(schema["properties"]["geometry"]["properties"]["height"]["x-methods"],
            nlohmann::json::array({"fe"}));
  EXPECT_EQ(schema["properties"]["method"]["enum"], nlohmann::json::array({"fe", "spectral_bi"}));
}

} // namespace
} // namespace slipfront::api
