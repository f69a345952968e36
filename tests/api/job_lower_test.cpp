// The `lower` section of a job (docs/api-job-spec.md "lower"): the rigid plane by default,
// with the hashes of the records made before the section existed; an elastic lower solid with
// its own material, height and bottom boundary (FE); every field of it refused by name when
// the plane is rigid or the method has no use for it.
#include "api/job_spec.hpp"
#include "solver/mesh_size.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using nlohmann::json;
using slipfront::api::FieldError;
using slipfront::api::parse_job;
using slipfront::api::ParseResult;

namespace {

const json elastic_lower = json::parse(R"({"solid": "elastic", "density": 2.0,
  "young_modulus": 5.0, "poisson_ratio": 0.3, "height": 10, "bottom_boundary": "absorbing"})");

// The reason of the error at `pointer`, or "" (and a failure listing the errors) if none.
std::string reason_at(const ParseResult& result, const std::string& pointer) {
  const auto found = std::find_if(result.errors.begin(), result.errors.end(),
                                  [&](const FieldError& e) { return e.pointer == pointer; });
  if (found != result.errors.end()) return found->reason;
  std::string got;
  for (const auto& e : result.errors)
    got += "\n  " + e.pointer + ": " + e.reason;
  ADD_FAILURE() << "no error at \"" << pointer << "\"; errors:" << got;
  return "";
}

std::string hash_of(const json& job) {
  const ParseResult result = parse_job(job);
  EXPECT_TRUE(result.ok()) << job.dump();
  return result.ok() ? result.spec->sha256 : "";
}

} // namespace

// The hashes of the paper's scene as the code before the `lower` section gave them (the
// result cache and the studies' scenes are keyed by them).
TEST(JobLower, TheRigidPlaneKeepsTheHashesOfOlderRecords) {
  EXPECT_EQ(hash_of(json::object()),
            "84a732aa727ba59e2cebb16298b9367636236d781bbc94dceb85a98c5dbe6f48");
  EXPECT_EQ(hash_of({{"lower", {{"solid", "rigid"}}}}), hash_of(json::object()));
  EXPECT_EQ(hash_of({{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 20}}}}),
            "c227394322ce23e0a419453734c0678bdc84cda38ebefe2220ef97b0f3831835");
  const ParseResult rigid = parse_job({{"lower", json::object()}});
  ASSERT_TRUE(rigid.ok());
  EXPECT_EQ(rigid.spec->canonical["lower"], json::parse(R"({"solid": "rigid"})"));
  EXPECT_FALSE(rigid.spec->params.lower.elastic());
  EXPECT_EQ(slipfront::api::scene_hash(rigid.spec->canonical),
            slipfront::api::scene_hash(parse_job(json::object()).spec->canonical));
}

TEST(JobLower, AnElasticLowerSolidIsMappedOntoParamsAndEntersTheHash) {
  const ParseResult result = parse_job({{"lower", elastic_lower}});
  ASSERT_TRUE(result.ok()) << result.errors.front().pointer << ": " << result.errors.front().reason;
  const slipfront::LowerSolid& lower = result.spec->params.lower;
  EXPECT_TRUE(lower.elastic());
  EXPECT_EQ(lower.material.density, 2.0);
  EXPECT_EQ(lower.material.young_modulus, 5.0);
  EXPECT_EQ(lower.material.poisson_ratio, 0.3);
  EXPECT_EQ(lower.height, 10.0);
  EXPECT_FALSE(lower.auto_height);
  EXPECT_EQ(lower.bottom, slipfront::TopBoundary::absorbing);
  EXPECT_EQ(result.spec->canonical["lower"], elastic_lower);

  // Every field of the lower solid is physics.
  const std::string hash = result.spec->sha256;
  EXPECT_NE(hash, hash_of(json::object()));
  for (const auto& [key, value] :
       std::vector<std::pair<std::string, json>>{{"density", 3.0},
                                                 {"young_modulus", 6.0},
                                                 {"poisson_ratio", 0.25},
                                                 {"height", 12},
                                                 {"bottom_boundary", "traction"}}) {
    json changed = elastic_lower;
    changed[key] = value;
    EXPECT_NE(hash_of({{"lower", changed}}), hash) << key;
  }
  // The defaults of an elastic lower solid are the upper solid's material and block.
  const ParseResult defaults = parse_job({{"lower", {{"solid", "elastic"}}}});
  ASSERT_TRUE(defaults.ok());
  EXPECT_EQ(defaults.spec->canonical["lower"],
            json::parse(R"({"solid": "elastic", "density": 1.0, "young_modulus": 2.5,
                            "poisson_ratio": 0.25, "height": 20.0,
                            "bottom_boundary": "traction"})"));
  EXPECT_EQ(parse_job(defaults.spec->canonical).spec->sha256, defaults.spec->sha256);
}

TEST(JobLower, AutoHeightUsesTheLowerSolidsPWaveSpeed) {
  json lower = {{"solid", "elastic"}, {"young_modulus", 10.0}, {"height", "auto"}};
  const ParseResult result =
      parse_job({{"lower", lower}, {"time", {{"duration", 4}}}, {"geometry", {{"height", 5}}}});
  ASSERT_TRUE(result.ok()) << result.errors.front().pointer << ": " << result.errors.front().reason;
  const slipfront::SimulationParams& p = result.spec->params;
  EXPECT_TRUE(p.lower.auto_height);
  EXPECT_EQ(result.spec->canonical["lower"]["height"], "auto");
  // c_p of the lower solid is twice the upper's (E four times): h = c_p T / 2 in whole
  // elements plus one (solver/mesh_size.hpp).
  const double c_p = p.lower.material.p_wave_speed();
  EXPECT_NEAR(c_p, 2.0 * p.material.p_wave_speed(), 1e-12);
  const slipfront::MeshSize m = slipfront::lower_mesh_size(p);
  EXPECT_EQ(m.ny - 1, int(std::ceil(0.5 * c_p * 4.0 * 40.0 - 1e-9)) + 1);
  EXPECT_EQ(slipfront::mesh_size(p).ny, 201); // the upper block keeps its 5 m
}

TEST(JobLower, ElasticFieldsOnTheRigidPlaneAreErrorsNamingEachField) {
  const ParseResult result =
      parse_job({{"lower", {{"density", 2.0}, {"height", 5}, {"bottom_boundary", "absorbing"}}}});
  ASSERT_FALSE(result.ok());
  EXPECT_EQ(result.errors.size(), 3u);
  for (const char* pointer : {"/lower/density", "/lower/height", "/lower/bottom_boundary"})
    EXPECT_NE(reason_at(result, pointer).find("only with \"solid\": \"elastic\""),
              std::string::npos)
        << pointer;
  // ... and so is a field no lower solid has.
  EXPECT_NE(
      reason_at(parse_job({{"lower", {{"solid", "elastic"}, {"colour", 1}}}}), "/lower/colour")
          .find("unknown"),
      std::string::npos);
}

TEST(JobLower, TheLowerSolidsFieldsAreRangeChecked) {
  const auto refused = [](const json& lower, const std::string& pointer,
                          const std::string& fragment) {
    json job_lower = {{"solid", "elastic"}};
    job_lower.update(lower);
    const std::string reason = reason_at(parse_job({{"lower", job_lower}}), pointer);
    EXPECT_NE(reason.find(fragment), std::string::npos) << pointer << ": " << reason;
  };
  refused({{"solid", "soft"}}, "/lower/solid", "rigid");
  refused({{"density", 0}}, "/lower/density", "> 0");
  refused({{"young_modulus", -1}}, "/lower/young_modulus", "> 0");
  refused({{"poisson_ratio", 0.5}}, "/lower/poisson_ratio", "");
  refused({{"height", 0}}, "/lower/height", "\"auto\"");
  refused({{"height", 5.01}}, "/lower/height", "whole");
  refused({{"bottom_boundary", "open"}}, "/lower/bottom_boundary", "absorbing");
  // The lower solid's wave speeds are bounded like the upper one's, the error at its field.
  const ParseResult overflow =
      parse_job({{"lower", {{"solid", "elastic"}, {"young_modulus", 1e300}, {"density", 1e-300}}}});
  ASSERT_EQ(overflow.errors.size(), 1u);
  EXPECT_EQ(overflow.errors[0].pointer.rfind("/lower/", 0), 0u) << overflow.errors[0].pointer;
  EXPECT_NE(overflow.errors[0].reason.find("wave speeds"), std::string::npos);
  refused({{"height", "auto"}, {"young_modulus", 1e12}}, "/lower/height", "auto");
}

TEST(JobLower, SpectralBiTakesTheLowerSolidAsAHalfSpace) {
  const json lower = {{"solid", "elastic"}, {"density", 2.0}, {"young_modulus", 5.0}};
  const ParseResult bi = parse_job({{"method", "spectral_bi"}, {"lower", lower}});
  ASSERT_TRUE(bi.ok()) << bi.errors.front().pointer << ": " << bi.errors.front().reason;
  EXPECT_TRUE(bi.spec->params.lower.elastic());
  EXPECT_FALSE(bi.spec->canonical["lower"].contains("height"));
  EXPECT_FALSE(bi.spec->canonical["lower"].contains("bottom_boundary"));
  // A half-space has no height and no far boundary.
  json with_height = lower;
  with_height["height"] = 5;
  with_height["bottom_boundary"] = "absorbing";
  const ParseResult refused = parse_job({{"method", "spectral_bi"}, {"lower", with_height}});
  EXPECT_NE(reason_at(refused, "/lower/height").find("half-space"), std::string::npos);
  EXPECT_NE(reason_at(refused, "/lower/bottom_boundary").find("half-space"), std::string::npos);
  // The same two solids by FE: the scene of the BI job is its counterpart (the block's height
  // and bottom boundary dropped).
  json fe_lower = lower;
  fe_lower["height"] = 10;
  const ParseResult fe = parse_job({{"lower", fe_lower}, {"geometry", {{"height", 10}}}});
  ASSERT_TRUE(fe.ok());
  EXPECT_EQ(slipfront::api::counterpart_scene_hash(fe.spec->canonical),
            slipfront::api::scene_hash(bi.spec->canonical));
  EXPECT_EQ(slipfront::api::counterpart_scene_hash(bi.spec->canonical),
            slipfront::api::scene_hash(
                parse_job({{"lower", lower}, {"geometry", json::object()}}).spec->canonical));
}
