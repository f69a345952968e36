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

// A field of an elastic lower solid (read only with "lower": {"solid": "elastic"}).
bool elastic_lower_field(const std::string& pointer) {
  return pointer.rfind("/lower/", 0) == 0 && pointer != "/lower/solid";
}

// A job with `value` at `pointer`, the method the field belongs to and, for the fields of a
// lower solid, the elastic lower solid.
nlohmann::json job_with(const JobField& field, const nlohmann::json& value) {
  nlohmann::json job = nlohmann::json::object();
  if (!field.fe) job["method"] = "spectral_bi";
  if (elastic_lower_field(field.pointer)) job["lower"]["solid"] = "elastic";
  job[nlohmann::json::json_pointer(field.pointer)] = value;
  return job;
}

bool has_error_at(const ParseResult& result, const std::string& pointer) {
  return std::any_of(result.errors.begin(), result.errors.end(),
                     [&](const FieldError& e) { return e.pointer == pointer; });
}

TEST(JobSchema, EveryFieldHasAUnitAndMeaningAndNoWordsAreLeftOver) {
  std::set<std::string> fields, documented;
  for (const JobField& f : job_fields()) {
    fields.insert(f.pointer);
    EXPECT_FALSE(f.meaning.empty()) << f.pointer;
    EXPECT_TRUE(f.schema.contains("default")) << f.pointer;
    EXPECT_TRUE(f.fe || f.spectral_bi) << f.pointer;
  }
  for (const std::string& p : documented_job_pointers())
    documented.insert(p);
  EXPECT_EQ(fields, documented);
  EXPECT_GE(fields.size(), 37u); // the job of docs/api-job-spec.md and the two method sections
}

TEST(JobSchema, MethodSpecificFieldsAreMarked) {
  std::set<std::string> fe_only, bi_only;
  for (const JobField& f : job_fields()) {
    if (!f.spectral_bi) fe_only.insert(f.pointer);
    if (!f.fe) bi_only.insert(f.pointer);
  }
  EXPECT_EQ(fe_only, (std::set<std::string>{"/fe/mesh_damping", "/geometry/height",
                                            "/geometry/top_boundary", "/lower/bottom_boundary",
                                            "/lower/height", "/time/safety_factor"}));
  EXPECT_EQ(bi_only,
            (std::set<std::string>{"/spectral_bi/corrector_passes", "/spectral_bi/memory_periods",
                                   "/spectral_bi/time_step_factor"}));
}

// The default the schema states is what a job without the field gets.
TEST(JobSchema, DefaultsAreTheCanonicalValuesOfAnEmptyJob) {
  const ParseResult fe = parse_job(nlohmann::json::object());
  const ParseResult bi = parse_job({{"method", "spectral_bi"}});
  const ParseResult lower = parse_job({{"lower", {{"solid", "elastic"}}}}); // its fields
  // Without stations, "stations" stays out of the canonical form (so that the specs written
  // before it existed keep their hashes); its other defaults are those of a job with one.
  const ParseResult one_station = parse_job({{"stations", {{"x1", {0.0}}}}});
  ASSERT_TRUE(fe.errors.empty() && bi.errors.empty() && lower.errors.empty() &&
              one_station.errors.empty());
  EXPECT_FALSE(fe.spec->canonical.contains("stations"));
  EXPECT_FALSE(bi.spec->canonical.contains("stations"));
  for (const JobField& f : job_fields()) {
    if (f.pointer == "/stations/x1") {
      EXPECT_EQ(f.schema["default"], nlohmann::json::array());
      continue;
    }
    const bool station_field = f.pointer.starts_with("/stations/");
    const nlohmann::json& canonical = station_field                    ? one_station.spec->canonical
                                      : elastic_lower_field(f.pointer) ? lower.spec->canonical
                                      : f.fe                           ? fe.spec->canonical
                                                                       : bi.spec->canonical;
    EXPECT_EQ(canonical.at(nlohmann::json::json_pointer(f.pointer)), f.schema["default"])
        << f.pointer;
  }
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
      EXPECT_TRUE(has_error_at(parse_job(job_with(f, beyond)), f.pointer))
          << f.pointer << " = " << beyond << " should be refused (" << key << " " << bound << ")";
      const bool narrowed = f.pointer == "/output/space_stride" && std::string(key) == "maximum";
      EXPECT_EQ(has_error_at(parse_job(job_with(f, bound)), f.pointer), open || narrowed)
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
