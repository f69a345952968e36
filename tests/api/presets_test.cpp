// The presets (api/presets.hpp): every preset is a valid job by both methods, a job that
// names one is that preset with the job's members merged over it, and the stored spec is the
// expanded one (the same canonical form and hash as the written-out job).
#include "api/job_schema.hpp"
#include "api/job_spec.hpp"
#include "api/presets.hpp"

#include <gtest/gtest.h>

#include <set>

namespace slipfront::api {
namespace {

TEST(Presets, EveryPresetIsAValidJobByBothMethods) {
  ASSERT_FALSE(presets().empty());
  std::set<std::string> names;
  for (const Preset& preset : presets()) {
    SCOPED_TRACE(preset.name);
    EXPECT_TRUE(names.insert(preset.name).second) << "two presets share a name";
    EXPECT_FALSE(preset.title.empty());
    EXPECT_FALSE(preset.description.empty());
    for (const char* method : {"fe", "spectral_bi"}) {
      SCOPED_TRACE(method);
      nlohmann::json job = preset.spec;
      job["method"] = method;
      if (std::string(method) == "spectral_bi") job.erase("fe"); // FE-only options
      ParseResult parsed = parse_job(job);
      for (const FieldError& e : parsed.errors)
        ADD_FAILURE() << e.pointer << ": " << e.reason;
    }
  }
}

TEST(Presets, ExamplesAreInTheCatalogue) {
  const Preset* quick = find_preset("quick_nd10");
  ASSERT_NE(quick, nullptr);
  EXPECT_EQ(quick->origin, "examples");
  EXPECT_EQ(quick->spec["geometry"]["nodes_per_meter"], 10);
  EXPECT_EQ(find_preset("no_such_preset"), nullptr);
}

TEST(Presets, AJobNamingAPresetIsThePresetWithItsMembersMergedOver) {
  const Preset* quick = find_preset("quick_nd10");
  ASSERT_NE(quick, nullptr);
  // Objects merge member by member (the preset's geometry keeps nodes_per_meter, the job adds
  // width), anything else replaces, null removes.
  const nlohmann::json job = {{"preset", "quick_nd10"},
                              {"geometry", {{"width", 30}}},
                              {"tags", {"mine"}},
                              {"output", nullptr},
                              {"method", "spectral_bi"}};
  std::vector<FieldError> errors;
  const nlohmann::json expanded = expand_preset(job, errors);
  ASSERT_TRUE(errors.empty());
  EXPECT_FALSE(expanded.contains("preset"));
  EXPECT_EQ(expanded["geometry"]["nodes_per_meter"], 10);
  EXPECT_EQ(expanded["geometry"]["width"], 30);
  EXPECT_EQ(expanded["tags"], nlohmann::json::array({"mine"}));
  EXPECT_FALSE(expanded.contains("output"));
  EXPECT_EQ(expanded["friction"], quick->spec["friction"]);

  // The parsed job is the written-out one: same canonical form, same hash, no "preset" left.
  const ParseResult via_preset = parse_job(job);
  const ParseResult written_out = parse_job(expanded);
  ASSERT_TRUE(via_preset.ok() && written_out.ok());
  EXPECT_EQ(via_preset.spec->canonical, written_out.spec->canonical);
  EXPECT_EQ(via_preset.spec->sha256, written_out.spec->sha256);
  EXPECT_FALSE(via_preset.spec->canonical.contains("preset"));
  EXPECT_EQ(via_preset.spec->name, quick->spec["name"]);
}

TEST(Presets, AnUnknownPresetIsAnErrorAtSlashPresetListingTheNames) {
  for (const nlohmann::json& name : {nlohmann::json("nope"), nlohmann::json(3)}) {
    const ParseResult parsed = parse_job({{"preset", name}, {"threads", 1}});
    ASSERT_EQ(parsed.errors.size(), 1u);
    EXPECT_EQ(parsed.errors[0].pointer, "/preset");
    EXPECT_NE(parsed.errors[0].reason.find("quick_nd10"), std::string::npos)
        << parsed.errors[0].reason;
  }
  // And the errors of the expanded job name the job's fields as usual.
  const ParseResult bad = parse_job({{"preset", "quick_nd10"}, {"friction", {{"L", -1}}}});
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.errors[0].pointer, "/friction/L");
}

TEST(Presets, TheSchemaOffersThePresetNames) {
  const nlohmann::json schema = job_json_schema();
  const nlohmann::json& preset = schema["properties"]["preset"];
  ASSERT_TRUE(preset.is_object());
  EXPECT_EQ(preset["enum"].size(), presets().size());
}

} // namespace
} // namespace slipfront::api
