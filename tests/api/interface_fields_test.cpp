// The job's interface fields (api/interface_reader.hpp, api/interface_checks.hpp,
// api/material_reader.hpp): the friction laws and their values, the overstressed patch,
// `profiles`, the material in wave speeds; every refusal names its field, and the fields
// new with them leave the hash of every older job as it was (docs/api-job-spec.md).
#include "api/friction_fields.hpp"
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront::api {
namespace {

using nlohmann::json;

// The only error of `job`: at `pointer`, its reason containing every fragment.
void expect_error(const json& job, const std::string& pointer,
                  std::initializer_list<std::string> fragments) {
  const ParseResult result = parse_job(job);
  ASSERT_FALSE(result.ok()) << job.dump();
  EXPECT_FALSE(result.spec.has_value());
  std::string all;
  for (const FieldError& e : result.errors)
    all += "\n  " + e.pointer + ": " + e.reason;
  ASSERT_EQ(result.errors.size(), 1u) << job.dump() << all;
  EXPECT_EQ(result.errors[0].pointer, pointer) << all;
  for (const std::string& fragment : fragments)
    EXPECT_NE(result.errors[0].reason.find(fragment), std::string::npos) << all;
}

JobSpec parsed(const json& job) {
  ParseResult result = parse_job(job);
  if (!result.ok()) {
    ADD_FAILURE() << job.dump() << ": " << result.errors[0].pointer << ": "
                  << result.errors[0].reason;
    return {};
  }
  return *result.spec;
}

const json slip_weakening = {{"law", "slip_weakening"}, {"mu_s", 0.75}, {"mu_d", 0.5}};

TEST(InterfaceFields, SlipWeakeningValuesAreChecked) {
  expect_error({{"friction", {{"law", "slip_weakening"}, {"mu_s", 0.6}, {"mu_d", 0.7}}}},
               "/friction/mu_d", {"mu_d = 0.7 exceeds mu_s = 0.6 (the coefficient weakens)"});
  json job = {{"friction", slip_weakening}};
  job["friction"]["D_c"] = 0.0;
  expect_error(job, "/friction/D_c", {"> 0", "got 0"});
  job["friction"]["D_c"] = -1e-3;
  expect_error(job, "/friction/D_c", {"> 0"});
  // A profile may not make mu_d exceed mu_s either: the error names the entry and x1.
  job = {{"friction", slip_weakening}, {"profiles", {{{"x1_min", 5.0}, {"mu_d", 0.8}}}}};
  expect_error(job, "/profiles/0/mu_d", {"at x1 = 5 m", "mu_d = 0.8 exceeds mu_s = 0.75"});
}

TEST(InterfaceFields, AValueTheLawDoesNotUseIsRefused) {
  expect_error({{"friction", {{"mu_s", 0.7}}}}, "/friction/mu_s",
               {R"(not used by friction law "prakash_clifton")", "it uses mu, v_star, L"});
  expect_error({{"friction", {{"law", "slip_weakening"}, {"mu", 0.7}}}}, "/friction/mu",
               {R"("slip_weakening" with regularization "none")", "mu_s, mu_d, D_c"});
  expect_error({{"friction", {{"law", "slip_weakening"}, {"L", 1e-3}}}}, "/friction/L",
               {"not used"});
  expect_error({{"friction", {{"t_star", 1e-3}}}}, "/friction/t_star", {"prakash_clifton"});
  expect_error({{"friction", {{"regularization", "time_scale"}}}}, "/friction/regularization",
               {R"(implied by law "prakash_clifton")", "coulomb"});
  expect_error({{"friction", {{"law", "slip_weakening"}, {"strength_update", "exponential"}}}},
               "/friction/strength_update", {"only with a regularization"});
  // In a profile: the entry's field, with the law's own values named.
  expect_error({{"profiles", {{{"x1_min", 0.0}, {"mu_s", 1.0}}}}}, "/profiles/0/mu_s",
               {R"(not used by friction law "prakash_clifton")"});
  expect_error({{"friction", {{"law", "coulomb"}}}, {"profiles", {{{"L", 1e-3}}}}}, "/profiles/0/L",
               {R"("coulomb" with regularization "none")"});
  // With the time scale, t_star is the law's; with the slip scale it is not.
  EXPECT_TRUE(
      parse_job({{"friction", {{"law", "slip_weakening"}, {"regularization", "time_scale"}}},
                 {"profiles", {{{"x1_max", 0.0}, {"t_star", 2e-3}}}}})
          .ok());
  expect_error({{"friction", {{"law", "slip_weakening"}, {"regularization", "slip_scale"}}},
                {"profiles", {{{"x1_max", 0.0}, {"t_star", 2e-3}}}}},
               "/profiles/0/t_star", {"it uses mu_s, mu_d, D_c, v_star, L"});
}

TEST(InterfaceFields, TheInitialStateMustBeStuckOutsideThePatch) {
  // A profile raising the shear above mu |sigma0| on [5, 8]: the entry's field and x1.
  expect_error({{"profiles", {{{"x1_min", 5.0}, {"x1_max", 8.0}, {"shear_stress", 0.02}}}}},
               "/profiles/0/shear_stress", {"at x1 = 5 m", "not stuck", "0.02 Pa", "0.01125 Pa"});
  // ... or lowering mu (0.5 * 0.015 < 0.0105) beyond x1 = 5, or lowering the pressure.
  expect_error({{"profiles", {{{"x1_min", 5.0}, {"mu", 0.5}}}}}, "/profiles/0/mu",
               {"at x1 = 5 m", "not stuck"});
  expect_error({{"profiles", {{{"x1_max", -2.0}, {"normal_stress", -0.01}}}}},
               "/profiles/0/normal_stress", {"at x1 = -10 m", "not stuck"});
  // The entry applied last names the failure: the second lowers mu_s where the first was
  // fine.
  expect_error({{"friction", slip_weakening},
                {"profiles",
                 {{{"x1_min", 0.0}, {"shear_stress", 0.011}}, {{"x1_min", 20.0}, {"mu_s", 0.6}}}}},
               "/profiles/1/mu_s", {"at x1 = 20 m"});
  // `outside` is strict: the ends of the interval keep their values.
  EXPECT_TRUE(parse_job({{"profiles",
                          {{{"x1_min", -9.0}, {"x1_max", 29.0}, {"outside", true}, {"mu", 0.9}}}}})
                  .ok());
  expect_error(
      {{"profiles", {{{"x1_min", -9.0}, {"x1_max", 29.0}, {"outside", true}, {"mu", 0.5}}}}},
      "/profiles/0/mu", {"at x1 = -10 m"});
  // Without a profile the uniform load is named as before.
  expect_error({{"loading", {{"shear_stress", 0.012}}}}, "/loading/shear_stress",
               {"static strength"});
  // The overstressed patch may exceed the strength; outside it the load may not.
  EXPECT_TRUE(
      parse_job({{"nucleation", {{"type", "overstressed_patch"}, {"shear_stress", 0.2}}}}).ok());
}

TEST(InterfaceFields, TheOverstressedPatchLiesInTheDomainAndHoldsANode) {
  const json patch = {{"type", "overstressed_patch"}, {"x1_min", -1.0}, {"x1_max", 1.0}};
  json job = {{"nucleation", patch}};
  EXPECT_TRUE(parse_job(job).ok());
  job["nucleation"]["x1_max"] = 100.0; // the domain is [-10, 30)
  expect_error(job, "/nucleation/x1_max", {"in the domain [x_min, x_min + width) = [-10, 30)"});
  job["nucleation"]["x1_max"] = 1.0;
  job["nucleation"]["x1_min"] = -10.5;
  expect_error(job, "/nucleation/x1_min", {"in the domain"});
  job["nucleation"] = {{"type", "overstressed_patch"}, {"x1_min", 0.01}, {"x1_max", 0.02}};
  expect_error(job, "/nucleation/x1_max", {"holds no interface node", "dx = 0.025 m"});
  job["nucleation"] = {{"type", "overstressed_patch"}, {"x1_min", 2.0}, {"x1_max", 1.0}};
  expect_error(job, "/nucleation/x1_min", {"at most x1_max = 1"});
  // The ellipse's numbers with the patch, and the patch's with the ellipse, are refused.
  expect_error({{"nucleation", {{"type", "overstressed_patch"}, {"a", 1.0}}}}, "/nucleation/a",
               {R"(only with "type": "ellipse")"});
  expect_error({{"nucleation", {{"x1_min", 1.0}}}}, "/nucleation/x1_min",
               {R"(only with "type": "overstressed_patch")"});
}

TEST(InterfaceFields, ProfilesAreObjectsThatSetSomething) {
  expect_error({{"profiles", {json::object()}}}, "/profiles/0", {"sets nothing"});
  expect_error({{"profiles", {1.0}}}, "/profiles/0", {"must be an object"});
  expect_error({{"profiles", json::object()}}, "/profiles", {"array of at most 64"});
  expect_error({{"profiles", {{{"x1_min", 5.0}, {"x1_max", 1.0}, {"mu", 0.8}}}}},
               "/profiles/0/x1_min", {"at most x1_max = 1"});
  expect_error({{"profiles", {{{"normal_stress", 0.0}}}}}, "/profiles/0/normal_stress", {"< 0"});
  expect_error({{"profiles", {{{"mu", 0.8}, {"tau", 1.0}}}}}, "/profiles/0/tau", {"unknown field"});
  json many = json::array();
  for (int k = 0; k < 65; ++k)
    many.push_back({{"mu", 0.8}});
  expect_error({{"profiles", many}}, "/profiles", {"at most 64"});
}

TEST(InterfaceFields, ProfilesAndThePatchReachTheSolverParameters) {
  const JobSpec job =
      parsed({{"friction", slip_weakening},
              {"profiles",
               {{{"x1_min", -3.0}, {"x1_max", 3.0}, {"outside", true}, {"mu_s", 10.0}},
                {{"x1_max", 0.0}, {"normal_stress", -0.02}, {"D_c", 2e-3}}}},
              {"nucleation",
               {{"type", "overstressed_patch"},
                {"x1_min", -0.5},
                {"x1_max", 0.5},
                {"shear_stress", 0.02}}}});
  const SimulationParams& p = job.params;
  ASSERT_EQ(p.profiles.size(), 2u);
  EXPECT_EQ(p.profiles[0].x1_min, -3.0);
  EXPECT_TRUE(p.profiles[0].outside);
  ASSERT_EQ(p.profiles[0].friction.size(), 1u);
  EXPECT_EQ(p.profiles[0].friction[0].first, &FrictionValues::mu_s);
  EXPECT_EQ(p.profiles[0].friction[0].second, 10.0);
  EXPECT_EQ(p.profiles[1].x1_min, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(p.profiles[1].normal_stress, -0.02);
  EXPECT_FALSE(p.profiles[1].shear_stress.has_value());
  EXPECT_TRUE(p.nucleation.patch());
  EXPECT_EQ(p.nucleation.shear_stress, 0.02);
  EXPECT_EQ(p.friction.law, "slip_weakening");
}

TEST(InterfaceFields, MaterialInWaveSpeeds) {
  // SCEC TPV3's rock: rho 2670 kg/m^3, c_p 6000 m/s, c_s 3464 m/s.
  const JobSpec job = parsed(
      {{"material", {{"density", 2670.0}, {"p_wave_speed", 6000.0}, {"s_wave_speed", 3464.0}}},
       {"loading", {{"normal_stress", -120e6}, {"shear_stress", 70e6}}},
       {"geometry", {{"nodes_per_meter", 1.0}}}});
  const Material& m = job.params.material;
  const double shear_modulus = 2670.0 * 3464.0 * 3464.0;
  const double nu =
      (6000.0 * 6000.0 - 2 * 3464.0 * 3464.0) / (2 * (6000.0 * 6000.0 - 3464.0 * 3464.0));
  EXPECT_NEAR(m.poisson_ratio, nu, 1e-15);
  EXPECT_NEAR(m.young_modulus, 2 * shear_modulus * (1 + nu), 1e-15 * m.young_modulus);
  EXPECT_NEAR(m.s_wave_speed(), 3464.0, 1e-12 * 3464.0);
  EXPECT_NEAR(m.p_wave_speed(), 6000.0, 1e-12 * 6000.0);
  // Kept as given in the canonical form (and the hash).
  EXPECT_EQ(job.canonical["material"],
            json({{"density", 2670.0}, {"p_wave_speed", 6000.0}, {"s_wave_speed", 3464.0}}));
}

TEST(InterfaceFields, MaterialFormsAreNotMixedAndCpExceedsSqrt2Cs) {
  expect_error({{"material", {{"p_wave_speed", 1.4}, {"s_wave_speed", 1.0}}}},
               "/material/p_wave_speed",
               {"more than sqrt(2) * s_wave_speed = 1.41421356237 m/s", "Poisson ratio"});
  for (const double c_s : {1.0, 1.4, 2.0}) // c_p < sqrt(2) c_s, c_p = c_s (nu = -inf), c_p < c_s
    expect_error({{"material", {{"p_wave_speed", 1.4}, {"s_wave_speed", c_s}}}},
                 "/material/p_wave_speed", {"more than sqrt(2)"});
  expect_error({{"material", {{"p_wave_speed", 2.0}, {"s_wave_speed", 0.0}}}},
               "/material/s_wave_speed", {"> 0"});
  expect_error({{"material", {{"p_wave_speed", 2.0}, {"s_wave_speed", -1.0}}}},
               "/material/s_wave_speed", {"> 0"});
  expect_error({{"material", {{"p_wave_speed", 2.0}}}}, "/material/s_wave_speed",
               {"required with p_wave_speed"});
  expect_error(
      {{"material", {{"p_wave_speed", 2.0}, {"s_wave_speed", 1.0}, {"poisson_ratio", 0.3}}}},
      "/material/poisson_ratio", {"cannot be mixed"});
  expect_error({{"material", {{"p_wave_speed", 1e200}, {"s_wave_speed", 1e-200}}}},
               "/material/p_wave_speed", {"rounds to 0.5"});
}

TEST(InterfaceFields, RunLimitsNameTheWaveSpeedsTheMaterialWasGivenIn) {
  // The limits of a run (api/run_bounds.hpp) name E and nu for a material in moduli; for
  // one in wave speeds they name the speed the job gave.
  expect_error({{"material", {{"p_wave_speed", 1e120}, {"s_wave_speed", 1e119}}}},
               "/material/s_wave_speed", {"time step would be as short as"});
  expect_error(
      {{"method", "spectral_bi"}, {"material", {{"p_wave_speed", 2000.0}, {"s_wave_speed", 1.0}}}},
      "/material/p_wave_speed", {"c_p / c_s = 2e+03"});
}

TEST(InterfaceFields, NewFieldsAtTheirDefaultsKeepEveryHash) {
  const JobSpec paper = parsed(json::object());
  // Explicit defaults of the new fields: the same canonical form, the same hash.
  const JobSpec explicit_defaults =
      parsed({{"nucleation", {{"type", "ellipse"}}}, {"profiles", json::array()}});
  EXPECT_EQ(explicit_defaults.canonical, paper.canonical);
  EXPECT_EQ(explicit_defaults.sha256, paper.sha256);
  EXPECT_EQ(scene_hash(explicit_defaults.canonical), scene_hash(paper.canonical));
  // Plain coulomb as it was written before the regularisation was a field, with L, v_star
  // and strength_update as it always took them.
  const json old_coulomb = {{"friction", {{"law", "coulomb"}, {"L", 1e-5}}}};
  const JobSpec coulomb = parsed(old_coulomb);
  EXPECT_EQ(coulomb.canonical["friction"], json({{"law", "coulomb"},
                                                 {"mu", 0.75},
                                                 {"L", 1e-5},
                                                 {"v_star", 1e-4},
                                                 {"strength_update", "exponential_ramp"}}));
  const JobSpec coulomb_none =
      parsed({{"friction", {{"law", "coulomb"}, {"L", 1e-5}, {"regularization", "none"}}}});
  EXPECT_EQ(coulomb_none.sha256, coulomb.sha256);
}

TEST(InterfaceFields, CoulombWithTheSlipScaleIsPrakashClifton) {
  const JobSpec pc = parsed({{"friction", {{"L", 1e-4}, {"v_star", 2e-4}}}});
  const JobSpec same = parsed(
      {{"friction",
        {{"law", "coulomb"}, {"regularization", "slip_scale"}, {"L", 1e-4}, {"v_star", 2e-4}}}});
  EXPECT_EQ(same.canonical, pc.canonical);
  EXPECT_EQ(same.sha256, pc.sha256);
  EXPECT_EQ(same.params.friction.law, "prakash_clifton");
  // The time scale is another physics, another hash.
  const JobSpec time_scale =
      parsed({{"friction", {{"law", "coulomb"}, {"regularization", "time_scale"}}}});
  EXPECT_NE(time_scale.sha256, pc.sha256);
  EXPECT_EQ(time_scale.canonical["friction"], json({{"law", "coulomb"},
                                                    {"mu", 0.75},
                                                    {"regularization", "time_scale"},
                                                    {"t_star", 1e-3},
                                                    {"strength_update", "exponential_ramp"}}));
}

} // namespace
} // namespace slipfront::api

namespace slipfront::api {
namespace {

// The companion of an L search takes the regularisation away and keeps the coefficient, each
// law as its description says; the job it makes validates.
TEST(InterfaceFields, TheUnregularisedPatchKeepsTheCoefficient) {
  auto patch_of = [](const json& friction) {
    const ParseResult r = parse_job({{"friction", friction}});
    EXPECT_TRUE(r.ok()) << friction.dump();
    return r.ok() ? unregularized_patch(r.spec->params.friction) : json();
  };
  EXPECT_EQ(patch_of({{"law", "prakash_clifton"}}), (json{{"law", "coulomb"}}));
  EXPECT_EQ(patch_of({{"law", "coulomb"}}), json::object());
  EXPECT_EQ(patch_of({{"law", "slip_weakening"}, {"regularization", "time_scale"}}),
            (json{{"regularization", "none"}, {"t_star", nullptr}, {"strength_update", nullptr}}));
  const json rsf = {{"law", "rate_and_state"}, {"regularization", "slip_scale"}, {"L", 1e-3}};
  EXPECT_EQ(patch_of(rsf),
            (json{{"regularization", "none"}, {"L", nullptr}, {"strength_update", nullptr}}));
  // The patched friction is a valid job: rate-and-state keeps v_star, its own reference rate.
  json bare = rsf;
  bare.merge_patch(patch_of(rsf));
  const ParseResult r = parse_job({{"friction", bare}});
  EXPECT_TRUE(r.ok()) << (r.ok() ? "" : r.errors.front().pointer + ": " + r.errors.front().reason);
}

} // namespace
} // namespace slipfront::api
