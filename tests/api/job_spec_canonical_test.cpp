// The canonical form of a job and its hash: equal physics, equal hash.
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

using nlohmann::json;
using slipfront::api::parse_job;
using slipfront::api::parse_job_text;

namespace {

slipfront::api::JobSpec parsed(const json& job) {
  auto result = parse_job(job);
  if (!result.ok()) {
    ADD_FAILURE() << result.errors.front().pointer << ": " << result.errors.front().reason;
    return {};
  }
  return *result.spec;
}

std::string hash_of(const json& job) {
  return parsed(job).sha256;
}

} // namespace

TEST(JobCanonical, EveryFieldIsFilledWithItsDefault) {
  const json canonical = parsed(json::object()).canonical;
  const json expected = json::parse(R"({
    "fe": {"mesh_damping": 0.0},
    "friction": {"L": 5e-05, "law": "prakash_clifton", "mu": 0.75,
                 "strength_update": "exponential_ramp", "v_star": 0.0001},
    "geometry": {"height": 20.0, "nodes_per_meter": 40.0, "top_boundary": "traction",
                 "width": 40.0, "x_min": -10.0},
    "loading": {"normal_stress": -0.015, "shear_stress": 0.0105},
    "lower": {"solid": "rigid"},
    "material": {"density": 1.0, "poisson_ratio": 0.25, "young_modulus": 2.5},
    "method": "fe",
    "name": "",
    "nucleation": {"a": 0.6, "alpha": 0.8, "b": 3.6, "enabled": true, "v": 0.825},
    "output": {"interval": 0.02, "space_stride": 1},
    "probe": {"arrival_x1": 11.0, "front_threshold": 1e-06, "spectrum_x1": 6.0},
    "tags": [],
    "threads": 0,
    "time": {"arrest_window": 1.0, "duration": 16.0, "safety_factor": 0.5,
             "stop_on_arrest": true}
  })");
  EXPECT_EQ(canonical, expected) << canonical.dump(2);
}

TEST(JobCanonical, TextIsCompactWithSortedKeys) {
  const json canonical = parsed({{"name", "n"}, {"friction", {{"mu", 0.8}}}}).canonical;
  const std::string text = slipfront::api::canonical_text(canonical);
  EXPECT_EQ(text.find(' '), std::string::npos);
  EXPECT_EQ(text.find('\n'), std::string::npos);
  EXPECT_LT(text.find("\"friction\""), text.find("\"geometry\""));
  EXPECT_LT(text.find("\"L\""), text.find("\"law\"")); // byte order: upper case first
}

TEST(JobCanonical, AutoHeightStaysAuto) {
  const json canonical = parsed({{"geometry", {{"height", "auto"}}}}).canonical;
  EXPECT_EQ(canonical["geometry"]["height"], "auto");
  EXPECT_NE(hash_of({{"geometry", {{"height", "auto"}}}}), hash_of(json::object()));
}

TEST(JobCanonical, HashIgnoresKeyOrderWhitespaceAndExplicitDefaults) {
  const std::string empty = hash_of(json::object());
  const auto a =
      parse_job_text(R"({"friction": {"mu": 0.75, "L": 5e-5}, "time": {"duration": 16}})");
  const auto b = parse_job_text(R"({ "time" : { "duration" : 16.0 },
                                     "friction" : { "L" : 0.00005, "mu" : 0.75 } })");
  ASSERT_TRUE(a.ok());
  ASSERT_TRUE(b.ok());
  EXPECT_EQ(a.spec->sha256, b.spec->sha256);
  EXPECT_EQ(a.spec->sha256, empty);
  EXPECT_EQ(hash_of({{"geometry", {{"nodes_per_meter", 40}}}}), empty); // integer 40 == 40.0
}

TEST(JobCanonical, PhysicsChangesTheHash) {
  const std::string reference = hash_of(json::object());
  EXPECT_NE(hash_of({{"friction", {{"L", 1e-5}}}}), reference);
  EXPECT_NE(hash_of({{"geometry", {{"nodes_per_meter", 20}}}}), reference);
  EXPECT_NE(hash_of({{"probe", {{"arrival_x1", 10}}}}), reference);
  EXPECT_NE(hash_of({{"friction", {{"law", "coulomb"}}}}), reference);
  EXPECT_NE(hash_of({{"time", {{"stop_on_arrest", false}}}}), reference);
  EXPECT_NE(hash_of({{"friction", {{"L", 1e-5}}}}), hash_of({{"friction", {{"L", 1.0001e-5}}}}));
}

TEST(JobCanonical, NameTagsThreadsAndOutputDoNotChangeTheHash) {
  const std::string reference = hash_of(json::object());
  EXPECT_EQ(hash_of({{"name", "paper run"}, {"tags", {"paper", "L=5e-5"}}}), reference);
  EXPECT_EQ(hash_of({{"threads", 4}}), reference);
  EXPECT_EQ(hash_of({{"output", {{"interval", 0.1}, {"space_stride", 4}}}}), reference);
}

TEST(JobCanonical, NameAndTagsAreKeptInTheSpec) {
  const auto spec = parsed({{"name", "paper run"}, {"tags", {"paper", "nd40"}}});
  EXPECT_EQ(spec.name, "paper run");
  EXPECT_EQ(spec.canonical["name"], "paper run");
  EXPECT_EQ(spec.canonical["tags"], json({"paper", "nd40"}));
}

TEST(JobCanonical, CanonicalFormParsesToTheSameJob) {
  const auto first = parsed({{"friction", {{"L", 1e-5}}}, {"geometry", {{"height", "auto"}}}});
  const auto second = parsed(first.canonical);
  EXPECT_EQ(second.canonical, first.canonical);
  EXPECT_EQ(second.sha256, first.sha256);
}

TEST(JobCanonical, SpecHashIsTheSha256OfThePhysicsText) {
  const auto spec = parsed(json::object());
  json physics = spec.canonical;
  // "method": "fe", the undamped "fe" section and the rigid plane below are left out: an FE
  // spec hashes as it did before those fields existed.
  for (const char* key : {"name", "tags", "threads", "output", "method", "fe", "lower"})
    physics.erase(key);
  EXPECT_EQ(spec.sha256, slipfront::api::sha256_hex(physics.dump()));
  EXPECT_EQ(slipfront::api::spec_hash(spec.canonical), spec.sha256);
}

TEST(JobCanonical, SpectralBiCanonicalHasItsSectionAndNoBlockFields) {
  const auto spec = parsed({{"method", "spectral_bi"}, {"friction", {{"L", 5e-6}}}});
  const json& c = spec.canonical;
  EXPECT_EQ(c["method"], "spectral_bi");
  EXPECT_EQ(
      c["spectral_bi"],
      json::parse(R"({"corrector_passes": 1, "memory_periods": 8.0, "time_step_factor": 0.5})"));
  EXPECT_FALSE(c["geometry"].contains("height"));
  EXPECT_FALSE(c["geometry"].contains("top_boundary"));
  EXPECT_FALSE(c["time"].contains("safety_factor"));
  // The method is part of the physics: the same scene by FE hashes differently.
  EXPECT_NE(spec.sha256, hash_of({{"friction", {{"L", 5e-6}}}}));
  EXPECT_EQ(hash_of({{"method", "fe"}}), hash_of(json::object()));
  EXPECT_NE(hash_of({{"method", "spectral_bi"}, {"spectral_bi", {{"memory_periods", 16}}}}),
            hash_of({{"method", "spectral_bi"}}));
}

TEST(JobCanonical, FeMeshDampingIsInTheFeCanonicalAndHashOnlyWhenOn) {
  const auto off = parsed(json::object());
  EXPECT_EQ(off.canonical["fe"], json::parse(R"({"mesh_damping": 0.0})"));
  // Zero damping is the scheme of every older record: the hash stays theirs.
  EXPECT_EQ(hash_of({{"fe", {{"mesh_damping", 0}}}}), off.sha256);
  EXPECT_EQ(hash_of({{"method", "fe"}, {"fe", json::object()}}), off.sha256);
  const auto on = parsed({{"fe", {{"mesh_damping", 0.5}}}});
  EXPECT_EQ(on.canonical["fe"]["mesh_damping"], 0.5);
  EXPECT_NE(on.sha256, off.sha256);
  EXPECT_NE(on.sha256, hash_of({{"fe", {{"mesh_damping", 0.25}}}}));
  EXPECT_EQ(parsed(on.canonical).sha256, on.sha256);
  // The BI canonical form has no "fe" section.
  EXPECT_FALSE(parsed({{"method", "spectral_bi"}}).canonical.contains("fe"));
}
