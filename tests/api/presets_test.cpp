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
      // Written out, and named with the method: the same job.
      ParseResult parsed = parse_job(preset_job(preset, method));
      const ParseResult named = parse_job({{"preset", preset.name}, {"method", method}});
      ASSERT_EQ(parsed.ok(), named.ok());
      if (parsed.ok()) {
        EXPECT_EQ(parsed.spec->sha256, named.spec->sha256);
      }
      for (const FieldError& e : parsed.errors)
        ADD_FAILURE() << e.pointer << ": " << e.reason;
    }
  }
}

TEST(Presets, FeOnlyMembersApplyToFeJobsOnly) {
  const Preset* tpv3 = find_preset("scec_tpv3_2d");
  ASSERT_NE(tpv3, nullptr);
  ASSERT_FALSE(tpv3->own.at("fe").empty());
  std::vector<FieldError> errors;
  const nlohmann::json fe = expand_preset({{"preset", "scec_tpv3_2d"}}, errors);
  const nlohmann::json bi =
      expand_preset({{"preset", "scec_tpv3_2d"}, {"method", "spectral_bi"}}, errors);
  ASSERT_TRUE(errors.empty());
  EXPECT_EQ(fe["lower"]["height"], "auto");
  EXPECT_FALSE(bi["lower"].contains("height"));
  EXPECT_EQ(bi["lower"]["s_wave_speed"], 3464);
  // The job's own members still win over the FE members.
  const nlohmann::json mine =
      expand_preset({{"preset", "scec_tpv3_2d"}, {"lower", {{"height", 30000}}}}, errors);
  EXPECT_EQ(mine["lower"]["height"], 30000);
}

TEST(Presets, TheSceneNumbersAreTheIssuesWords) {
  // SCEC TPV3 in 2-D and the two bimaterial scenes, with the numbers they were
  // specified with (docs/presets.md).
  const Preset* tpv3 = find_preset("scec_tpv3_2d");
  const Preset* sw = find_preset("bimaterial_slip_weakening");
  const Preset* pc = find_preset("bimaterial_prakash_clifton");
  ASSERT_TRUE(tpv3 && sw && pc);
  const nlohmann::json& t = tpv3->spec;
  EXPECT_EQ(t["material"],
            (nlohmann::json{{"density", 2670}, {"p_wave_speed", 6000}, {"s_wave_speed", 3464}}));
  EXPECT_EQ(t["loading"]["normal_stress"], -120e6);
  EXPECT_EQ(t["loading"]["shear_stress"], 70e6);
  EXPECT_EQ(t["nucleation"]["shear_stress"], 81.6e6);
  EXPECT_EQ(t["nucleation"]["x1_max"], 1500);
  EXPECT_EQ(t["friction"]["mu_s"], 0.677);
  EXPECT_EQ(t["friction"]["mu_d"], 0.525);
  EXPECT_EQ(t["friction"]["D_c"], 0.4);
  EXPECT_EQ(t["profiles"][0]["mu_s"], 10000);
  EXPECT_EQ(t["time"]["duration"], 16);
  EXPECT_EQ(t["stations"]["x1"], (nlohmann::json{0, 4500, 7500, 12000}));
  for (const Preset* b : {sw, pc}) {
    EXPECT_EQ(b->spec["material"]["s_wave_speed"], 2620);
    EXPECT_EQ(b->spec["lower"]["s_wave_speed"], 3091.6);
    EXPECT_EQ(b->spec["lower"]["density"], 2745.739);
    EXPECT_EQ(b->spec["loading"]["normal_stress"], -130e6);
    EXPECT_EQ(b->spec["time"]["duration"], 0.1);
    EXPECT_GT(b->spec["loading"]["shear_stress"].get<double>(), 0); // upper towards +x1
  }
  EXPECT_EQ(sw->spec["geometry"]["width"], 600);
  EXPECT_EQ(sw->spec["friction"]["t_star"], 0.35e-3);
  EXPECT_EQ(sw->spec["friction"]["D_c"], 0.744e-3);
  EXPECT_EQ(sw->spec["nucleation"]["shear_stress"], 91.001e6);
  EXPECT_EQ(pc->spec["friction"]["L"], 1e-3);
  EXPECT_EQ(pc->spec["friction"]["v_star"], 0.26);
  EXPECT_EQ(pc->spec["nucleation"]["shear_stress"], 100.1e6);
  EXPECT_EQ(pc->spec["loading"]["shear_stress"], 89.18e6);
}

TEST(Presets, TheRateAndStateScenesAreAsStated) {
  // SEM2DPACK's example made in-plane (both state laws) and SCEC TPV101 in 2-D, as the
  // rate-and-state scenes state them (docs/presets.md).
  for (const char* name : {"rsf_slip_law_inplane", "rsf_aging_law_inplane"}) {
    const Preset* p = find_preset(name);
    ASSERT_NE(p, nullptr) << name;
    const nlohmann::json& s = p->spec;
    EXPECT_EQ(s["material"],
              (nlohmann::json{{"density", 2673}, {"p_wave_speed", 6000}, {"s_wave_speed", 3464}}));
    EXPECT_EQ(s["lower"]["solid"], "elastic");
    EXPECT_EQ(s["lower"]["density"], 2673);
    const nlohmann::json& f = s["friction"];
    EXPECT_EQ(f["law"], "rate_and_state");
    EXPECT_EQ(f["state_evolution"],
              std::string(name).find("slip") != std::string::npos ? "slip" : "aging");
    EXPECT_EQ(f["f0"], 0.6);
    EXPECT_EQ(f["a"], 0.0125);
    EXPECT_EQ(f["b"], 0.0172);
    EXPECT_EQ(f["D_c"], 0.037);
    EXPECT_EQ(f["v_star"], 1e-6);
    EXPECT_EQ(f["initial_slip_rate"], 1e-3);
    EXPECT_EQ(f["theta"], 4.0036e-14); // beyond 10 km
    EXPECT_EQ(s["loading"]["normal_stress"], -120e6);
    EXPECT_EQ(s["loading"]["shear_stress"], 0.01e6);
    EXPECT_EQ(s["profiles"][0]["shear_stress"], 70e6);
    EXPECT_EQ(s["profiles"][0]["theta"], 92.713);
    EXPECT_EQ(s["profiles"][0]["x1_max"], 9999.999);
    EXPECT_EQ(s["profiles"][1]["shear_stress"], 81.6e6);
    EXPECT_EQ(s["profiles"][1]["x1_max"], 1499.999);
    EXPECT_EQ(s["time"]["duration"],
              std::string(name).find("slip") != std::string::npos ? 2.5 : 3.2);
    EXPECT_EQ(s["stations"]["x1"], (nlohmann::json{0, 1500, 3000, 4500, 6000, 7500, 9000}));
    EXPECT_EQ(s["stations"]["rupture_threshold"], 0.1);
  }
  const Preset* t = find_preset("tpv101_2d");
  ASSERT_NE(t, nullptr);
  const nlohmann::json& f = t->spec["friction"];
  EXPECT_EQ(f["state_evolution"], "aging");
  EXPECT_EQ(f["b"], 0.012);
  EXPECT_EQ(f["D_c"], 0.02);
  EXPECT_EQ(f["a"], 0.016);
  EXPECT_EQ(t->spec["profiles"][0]["a"], 0.008);
  EXPECT_EQ(t->spec["profiles"][0]["x1_max"], 15000);
  EXPECT_EQ(t->spec["profiles"][0]["ramp"], 3000);
  EXPECT_EQ(f["initial_slip_rate"], 1e-12);
  EXPECT_EQ(f["initial_state"], "stress");
  EXPECT_EQ(t->spec["loading"]["shear_stress"], 75e6);
  EXPECT_EQ(t->spec["nucleation"]["shear_stress_increase"], 25e6);
  EXPECT_EQ(t->spec["nucleation"]["radius"], 3000);
  EXPECT_EQ(t->spec["nucleation"]["rise_time"], 1.0);
  EXPECT_EQ(t->spec["time"]["duration"], 12);
}

TEST(Presets, ExamplesAreInTheCatalogue) {
  const Preset* quick = find_preset("quick_nd10");
  ASSERT_NE(quick, nullptr);
  EXPECT_EQ(quick->origin, "examples");
  EXPECT_EQ(quick->spec["geometry"]["nodes_per_meter"], 10);
  EXPECT_EQ(find_preset("no_such_preset"), nullptr);
}

TEST(Presets, AnFeExamplesOwnMembersAreLeftOutByBi) {
  // examples/rock_patch_nd2.json gives both blocks "height": "auto": by FE the file itself, by
  // BI the half-spaces without them.
  const Preset* rock = find_preset("rock_patch_nd2");
  ASSERT_NE(rock, nullptr);
  const nlohmann::json fe = preset_job(*rock, "fe"), bi = preset_job(*rock, "spectral_bi");
  EXPECT_EQ(fe["geometry"]["height"], "auto");
  EXPECT_EQ(fe["lower"]["height"], "auto");
  EXPECT_FALSE(bi["geometry"].contains("height"));
  EXPECT_FALSE(bi["lower"].contains("height"));
  EXPECT_EQ(bi["geometry"]["nodes_per_meter"], fe["geometry"]["nodes_per_meter"]);
  EXPECT_TRUE(parse_job(fe).ok() && parse_job(bi).ok());
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
