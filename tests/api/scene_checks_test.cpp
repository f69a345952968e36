// The defaults at the job's own scale (api/scene_defaults.hpp) and the warnings of a valid
// job (api/scene_checks.hpp): each warning once triggered and once not; the paper's runs and
// the presets warn of nothing and keep their hashes; the rock-scale example derives what it
// does not give and, run on a coarse mesh, ends `arrested` at its barrier.
#include "api/job_spec.hpp"
#include "api/presets.hpp"
#include "api/scene_checks.hpp"
#include "solver/simulation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

using nlohmann::json;
using slipfront::api::FieldWarning;
using slipfront::api::parse_job;
using slipfront::api::ParseResult;
using slipfront::api::ValueSource;

namespace {

// A valid job (a test failure listing the errors otherwise).
slipfront::api::JobSpec valid(const json& job) {
  ParseResult r = parse_job(job);
  std::string errors;
  for (const auto& e : r.errors)
    errors += "\n  " + e.pointer + ": " + e.reason;
  EXPECT_TRUE(r.ok()) << job.dump() << errors;
  return r.ok() ? *r.spec : slipfront::api::JobSpec{};
}

std::string listed(const std::vector<FieldWarning>& warnings) {
  std::string text;
  for (const auto& w : warnings)
    text += "\n  " + w.pointer + ": " + w.message;
  return text;
}

// The warning at `pointer` (a failure listing them all if there is none).
const FieldWarning* warning_at(const std::vector<FieldWarning>& warnings,
                               const std::string& pointer) {
  const auto found = std::find_if(warnings.begin(), warnings.end(),
                                  [&](const FieldWarning& w) { return w.pointer == pointer; });
  if (found != warnings.end()) return &*found;
  ADD_FAILURE() << "no warning at " << pointer << "; got:" << listed(warnings);
  return nullptr;
}

bool warns_at(const std::vector<FieldWarning>& warnings, const std::string& pointer) {
  return std::any_of(warnings.begin(), warnings.end(),
                     [&](const FieldWarning& w) { return w.pointer == pointer; });
}

void expect_warning(const json& job, const std::string& pointer, const std::string& fragment) {
  const auto spec = valid(job);
  if (const FieldWarning* w = warning_at(spec.warnings, pointer)) {
    EXPECT_NE(w->message.find(fragment), std::string::npos) << w->message;
  }
}

void expect_no_warning(const json& job, const std::string& pointer) {
  const auto spec = valid(job);
  EXPECT_FALSE(warns_at(spec.warnings, pointer)) << job.dump() << listed(spec.warnings);
}

const ValueSource& source_of(const slipfront::api::JobSpec& spec, const std::string& pointer) {
  static const ValueSource none{};
  const auto found = std::find_if(spec.provenance.begin(), spec.provenance.end(),
                                  [&](const ValueSource& v) { return v.pointer == pointer; });
  if (found != spec.provenance.end()) return *found;
  ADD_FAILURE() << "no provenance for " << pointer;
  return none;
}

// The rock solid of the scene (granite-like).
const json rock = {{"density", 2670}, {"p_wave_speed", 6000}, {"s_wave_speed", 3464}};

// The rock-scale example (examples/rock_patch_nd2.json, a preset like every example), by FE:
// the file itself.
json rock_scene() {
  return slipfront::api::preset_job(*slipfront::api::find_preset("rock_patch_nd2"), "fe");
}

json merged(json base, const json& patch) {
  base.merge_patch(patch);
  return base;
}

} // namespace

TEST(SceneDefaults, ThePapersMaterialKeepsThePapersDefaults) {
  const auto spec = valid(json::object());
  EXPECT_TRUE(spec.warnings.empty()) << listed(spec.warnings);
  EXPECT_EQ(spec.params.time.arrest_window, 1.0);
  EXPECT_EQ(spec.params.output.interval, 0.02);
  EXPECT_EQ(spec.params.probes.arrival_x1, 11.0);
  EXPECT_EQ(spec.params.probes.spectrum_x1, 6.0);
  EXPECT_EQ(spec.params.probes.front_threshold, 1e-6);
  EXPECT_EQ(source_of(spec, "/time/arrest_window").source, "default");
  EXPECT_EQ(source_of(spec, "/time/arrest_window").unit, "s");
  EXPECT_EQ(source_of(spec, "/loading/normal_stress").value, -0.015);
  // The paper's material in its wave-speed form is the paper's material.
  const auto speeds = valid(
      {{"material", {{"density", 1}, {"s_wave_speed", 1}, {"p_wave_speed", std::sqrt(3.0)}}}});
  EXPECT_EQ(speeds.params.time.arrest_window, 1.0);
}

TEST(SceneDefaults, TheRockSceneDerivesWhatOnlyWatchesTheRun) {
  const auto spec = valid(rock_scene());
  EXPECT_TRUE(spec.warnings.empty()) << listed(spec.warnings);
  const auto& p = spec.params;
  EXPECT_DOUBLE_EQ(p.time.arrest_window, 0.005); // a tenth of 0.05 s
  EXPECT_DOUBLE_EQ(p.output.interval, 0.05 / 800);
  // The paper's 1e-6 m/s scaled by (|sigma| + |tau|) / (rho c_s): 190e6 / (2670 * 3464) m/s
  // against the paper's 0.0255 m/s.
  EXPECT_NEAR(p.probes.front_threshold, 1e-6 * (190e6 / (2670 * 3464.0)) / 0.0255, 1e-12);
  // Beyond the patch [-15, 15] towards +x1: two and a half patch lengths.
  EXPECT_DOUBLE_EQ(p.probes.arrival_x1, 75.0);
  EXPECT_DOUBLE_EQ(p.probes.spectrum_x1, 30.0);
  EXPECT_EQ(source_of(spec, "/time/arrest_window").source,
            "derived: a tenth of the duration 0.05 s");
  EXPECT_EQ(source_of(spec, "/probe/arrival_x1").source.rfind("derived: two patch lengths", 0), 0u);
  EXPECT_EQ(source_of(spec, "/material/density").source, "given");
  // The canonical form holds the values used.
  EXPECT_DOUBLE_EQ(spec.canonical["time"]["arrest_window"].get<double>(), 0.005);
  EXPECT_DOUBLE_EQ(spec.canonical["probe"]["arrival_x1"].get<double>(), 75.0);
  // A value the job gives is never derived.
  const auto given = valid(merged(rock_scene(), {{"time", {{"arrest_window", 0.002}}}}));
  EXPECT_DOUBLE_EQ(given.params.time.arrest_window, 0.002);
  EXPECT_EQ(source_of(given, "/time/arrest_window").source, "given");
}

TEST(SceneDefaults, TheArrestWindowIsAtMostAnSWavesTransitOfTheDomain) {
  // 80 m of rock is crossed in 23 ms, less than a tenth of 1 s.
  const auto spec = valid(merged(rock_scene(), {{"time", {{"duration", 1.0}}},
                                                {"geometry", {{"width", 80}, {"x_min", -40}}},
                                                {"profiles", json::array()}}));
  EXPECT_NEAR(spec.params.time.arrest_window, 80 / 3464.0, 1e-12);
}

TEST(SceneDefaults, ProbesFollowTheShearLoadsDirectionAndStayInTheDomain) {
  // A negative shear load drives towards -x1: the probes stand left of the patch.
  json job = rock_scene();
  job["loading"]["shear_stress"] = -70e6;
  job["nucleation"]["shear_stress"] = -81.6e6;
  const auto left = valid(job);
  EXPECT_DOUBLE_EQ(left.params.probes.arrival_x1, -75.0);
  EXPECT_DOUBLE_EQ(left.params.probes.spectrum_x1, -30.0);
  // A patch that nearly fills the domain: at most half and a quarter of the rest away, on a node
  // (the barrier left out, so that the whole patch may slip).
  const auto wide = valid(merged(rock_scene(), {{"nucleation", {{"x1_min", -180}, {"x1_max", 180}}},
                                                {"profiles", json::array()}}));
  EXPECT_DOUBLE_EQ(wide.params.probes.arrival_x1, -200.0); // 20 m past 180: the seam
  EXPECT_DOUBLE_EQ(wide.params.probes.spectrum_x1, 190.0);
  EXPECT_FALSE(warns_at(wide.warnings, "/probe/arrival_x1")) << listed(wide.warnings);
}

TEST(SceneDefaults, StationsTakeTheFrontThresholdUnlessGivenTheirOwn) {
  const auto one = valid({{"stations", {{"x1", {5.0}}}}});
  EXPECT_EQ(one.params.stations.rupture_threshold, 1e-6);
  EXPECT_EQ(source_of(one, "/stations/rupture_threshold").source.rfind("derived: the front", 0),
            0u);
  const auto two = valid({{"stations", {{"x1", {5.0}}, {"rupture_threshold", 1e-3}}}});
  EXPECT_EQ(two.params.stations.rupture_threshold, 1e-3);
  EXPECT_EQ(source_of(two, "/stations/rupture_threshold").source, "given");
  const auto rock_stations = valid(merged(rock_scene(), {{"stations", {{"x1", {30.0}}}}}));
  EXPECT_EQ(rock_stations.params.stations.rupture_threshold,
            rock_stations.params.probes.front_threshold);
}

TEST(SceneDefaults, APresetsValuesSayWhichPreset) {
  const auto spec = valid({{"preset", "scec_tpv3_2d"}, {"time", {{"duration", 12}}}});
  EXPECT_EQ(source_of(spec, "/material/density").source, "preset scec_tpv3_2d");
  EXPECT_EQ(source_of(spec, "/time/duration").source, "given");
}

TEST(SceneWarnings, ThePapersRunsAndThePresetsWarnOfNothing) {
  for (const auto& preset : slipfront::api::presets()) {
    for (const char* method : {"fe", "spectral_bi"}) {
      const auto spec = valid({{"preset", preset.name}, {"method", method}});
      EXPECT_TRUE(spec.warnings.empty()) << preset.name << " " << method << listed(spec.warnings);
    }
  }
}

TEST(SceneWarnings, ThePresetsKeepTheirHashes) {
  // The spec hashes of the scene presets before the defaults followed the scene's scale.
  const std::map<std::pair<std::string, std::string>, std::string> before = {
      {{"bimaterial_prakash_clifton", "fe"},
       "16b9e1616ba8f853b9166e881c6d034e2523f9b58e621cef815bf14da55f21fd"},
      {{"bimaterial_prakash_clifton", "spectral_bi"},
       "5c91ef3a373f8dfe68f175830f93622ed4f5f325d2e6f0c5795c4a5209293bf0"},
      {{"bimaterial_slip_weakening", "fe"},
       "9ccf1567d6cd94079a7d9a7c94238d64849efe17f8127bf31da021a74dfc12d3"},
      {{"bimaterial_slip_weakening", "spectral_bi"},
       "6cba2018e6e5651570e163a0c9eeacbefec442d82f46447963e037b0c6a94fd8"},
      {{"scec_tpv3_2d", "fe"}, "ba4ee96d9c563f8d23dbb44ce7828664703b0eb476d57293cccb367a6848ae62"},
      {{"scec_tpv3_2d", "spectral_bi"},
       "1db3d95c0106fed5bd58b3b845564e1c720a072ae5d29456490173aa8bed041f"},
  };
  for (const auto& [key, hash] : before)
    EXPECT_EQ(valid({{"preset", key.first}, {"method", key.second}}).sha256, hash)
        << key.first << " " << key.second;
}

TEST(SceneWarnings, APaperDefaultKeptForAnotherMaterial) {
  // Only the material given: every default of the physics is the paper's scaled units.
  const auto spec = valid({{"material", rock}});
  for (const char* pointer : {"/loading/normal_stress", "/loading/shear_stress", "/time/duration",
                              "/geometry/width", "/friction/L", "/nucleation/a"}) {
    if (const FieldWarning* w = warning_at(spec.warnings, pointer)) {
      EXPECT_NE(w->message.find("paper's scaled units"), std::string::npos) << w->message;
    }
  }
  // Measuring defaults are derived instead, and never warned about.
  EXPECT_FALSE(warns_at(spec.warnings, "/time/arrest_window")) << listed(spec.warnings);
  EXPECT_NE(source_of(spec, "/time/arrest_window").source.find("derived"), std::string::npos);
  // Plain coulomb does not read L and v_star: not warned.
  expect_no_warning({{"material", rock}, {"friction", {{"law", "coulomb"}}}}, "/friction/L");
  expect_no_warning(rock_scene(), "/time/duration");
}

TEST(SceneWarnings, StressesAgainstTheShearModulus) {
  // Rock stresses on the paper's solid (shear modulus 1 Pa).
  expect_warning({{"loading", {{"normal_stress", -120e6}, {"shear_stress", 70e6}}}},
                 "/loading/normal_stress", "times the shear modulus");
  // The paper's stresses on rock, all else given.
  expect_warning(
      merged(rock_scene(), {{"loading", {{"normal_stress", -0.015}, {"shear_stress", 0.009}}},
                            {"nucleation", {{"shear_stress", 0.012}}}}),
      "/loading/normal_stress", "of the shear modulus");
  expect_no_warning(json::object(), "/loading/normal_stress");
  expect_no_warning(rock_scene(), "/loading/normal_stress");
}

TEST(SceneWarnings, AProcessZoneFewElementsResolve) {
  // dx = 10 m against Lambda_0 = (9 pi/32) (mu / (1 - nu)) D_c / ((mu_s - mu_d) |sigma|) = 10.3 m.
  const auto coarse = valid(merged(rock_scene(), {{"geometry", {{"nodes_per_meter", 0.1}}}}));
  const double r = (3464.0 / 6000) * (3464.0 / 6000), nu = (1 - 2 * r) / (2 * (1 - r));
  const double zone =
      9 * std::numbers::pi / 32 * (2670 * 3464.0 * 3464 / (1 - nu)) * 0.005 / (0.152 * 120e6);
  EXPECT_NEAR(slipfront::api::static_process_zone(coarse.params), zone, 1e-9 * zone);
  if (const FieldWarning* w = warning_at(coarse.warnings, "/geometry/nodes_per_meter")) {
    EXPECT_NE(w->message.find("spans 1.035 elements"), std::string::npos) << w->message;
  }
  expect_no_warning(rock_scene(), "/geometry/nodes_per_meter");
  // On the rigid plane only one side deforms: twice the modulus, twice the zone.
  json rigid = rock_scene();
  rigid["lower"] = {{"solid", "rigid"}};
  EXPECT_NEAR(slipfront::api::static_process_zone(valid(rigid).params), 2 * zone, 1e-9 * zone);
  // A constant coefficient has no process zone.
  EXPECT_TRUE(std::isnan(slipfront::api::static_process_zone(valid(json::object()).params)));
}

TEST(SceneWarnings, TheRateAndStateProcessZoneAndItsRecord) {
  // The SEM2DPACK scene: Lambda_0 = (mu / (1 - nu)) D_c / (b |sigma|) for two identical solids.
  json scene = slipfront::api::preset_job(*slipfront::api::find_preset("rsf_slip_law_inplane"),
                                          "spectral_bi");
  const double r = (3464.0 / 6000) * (3464.0 / 6000), nu = (1 - 2 * r) / (2 * (1 - r));
  const double zone = (2673 * 3464.0 * 3464 / (1 - nu)) * 0.037 / (0.0172 * 120e6);
  const auto preset = valid(scene);
  EXPECT_NEAR(slipfront::api::static_process_zone(preset.params), zone, 1e-9 * zone);
  const json record = slipfront::api::resolution_json(preset.params);
  EXPECT_NEAR(record["elements"].get<double>(), zone * 0.04, 1e-9 * zone);
  EXPECT_NE(record["formula"].get<std::string>().find("b |normal_stress|"), std::string::npos);
  EXPECT_FALSE(warns_at(preset.warnings, "/geometry/nodes_per_meter")) << listed(preset.warnings);
  // About 767 m: at dx = 500 m it spans 1.5 elements, fewer than 3.
  expect_warning(merged(scene, {{"geometry", {{"nodes_per_meter", 0.002}}}}),
                 "/geometry/nodes_per_meter", "rate-and-state process zone");
  // A constant coefficient's record has no zone.
  EXPECT_TRUE(slipfront::api::resolution_json(valid(json::object()).params).is_null());
}

TEST(SceneWarnings, RateAndStateStrengtheningEverywhere) {
  json scene = slipfront::api::preset_job(*slipfront::api::find_preset("rsf_aging_law_inplane"),
                                          "spectral_bi");
  expect_no_warning(scene, "/friction/a");
  expect_warning(merged(scene, {{"friction", {{"a", 0.02}}}}), "/friction/a",
                 "velocity strengthening");
  // A profile that weakens a region (TPV101's a = 0.008 inside 15 km) is not warned.
  json tpv101 =
      slipfront::api::preset_job(*slipfront::api::find_preset("tpv101_2d"), "spectral_bi");
  ASSERT_GT(tpv101["friction"]["a"].get<double>(), tpv101["friction"]["b"].get<double>());
  expect_no_warning(tpv101, "/friction/a");
}

TEST(SceneWarnings, AnArrestWindowTheRunLeavesNoRoomFor) {
  // The ellipse is over at 4.42 s: 5 s leave 0.58 s, less than the paper's 1 s window.
  expect_warning({{"time", {{"duration", 5}}}}, "/time/arrest_window", "can never end `arrested`");
  expect_warning(merged(rock_scene(), {{"time", {{"arrest_window", 0.05}}}}), "/time/arrest_window",
                 "0.05 s after the nucleation ends");
  expect_no_warning(json::object(), "/time/arrest_window");
  expect_no_warning(rock_scene(), "/time/arrest_window");
}

TEST(SceneWarnings, ProbesAndStationsInsideTheNucleationPatch) {
  expect_warning({{"probe", {{"arrival_x1", 2}}}}, "/probe/arrival_x1",
                 "inside the nucleation patch");
  expect_warning({{"probe", {{"spectrum_x1", 1}}}}, "/probe/spectrum_x1",
                 "inside the nucleation patch");
  expect_warning({{"stations", {{"x1", {1, 2}}}}}, "/stations/x1", "every station");
  expect_no_warning({{"stations", {{"x1", {1, 5}}}}}, "/stations/x1");
  expect_no_warning(json::object(), "/probe/arrival_x1");
  expect_no_warning(json::object(), "/probe/spectrum_x1");
}

TEST(SceneWarnings, ADurationTooShortForTheNucleation) {
  expect_warning({{"time", {{"duration", 3}}}}, "/time/duration", "ellipse is over");
  expect_warning(merged(rock_scene(), {{"time", {{"duration", 0.005}}}}), "/time/duration",
                 "crosses the nucleation patch");
  expect_no_warning(json::object(), "/time/duration");
  expect_no_warning(rock_scene(), "/time/duration");
}

TEST(RockScene, EndsArrestedAtTheBarrierOnACoarseMesh) {
  // The example on a coarse mesh (dx = 2 m, the process zone 5 elements): the rupture grows from
  // the patch both ways and stops at the barrier |x1| = 100 m after about 36 ms; the derived
  // 5 ms window sees it and the run stops there (the n_d = 2 example: the same, at 41 ms).
  const auto spec = valid(merged(rock_scene(), {{"geometry", {{"nodes_per_meter", 0.5}}}}));
  EXPECT_TRUE(spec.warnings.empty()) << listed(spec.warnings);
  const slipfront::RunResult r = slipfront::run_simulation(spec.params);
  EXPECT_EQ(r.metrics.outcome, slipfront::Outcome::arrested);
  EXPECT_NEAR(r.metrics.arrest_position, 100.0, 2.0); // the last node before the barrier
  EXPECT_NEAR(r.metrics.propagation_distance, 200.0, 4.0);
  EXPECT_LT(r.metrics.simulated_time, 0.05);                   // stopped on arrest
  EXPECT_TRUE(std::isfinite(r.metrics.arrival_time_at_probe)); // the derived probe at 76 m
}
