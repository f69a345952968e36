// Validation of the job JSON: every rule names the field by its JSON pointer.
// Over 400 lines on purpose: one short TEST per rule of docs/api-job-spec.md.
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using nlohmann::json;
using slipfront::api::FieldError;
using slipfront::api::parse_job;
using slipfront::api::parse_job_text;
using slipfront::api::ParseResult;

namespace {

// The error at `pointer`, or a test failure listing every error got.
const FieldError* error_at(const ParseResult& result, const std::string& pointer) {
  const auto found = std::find_if(result.errors.begin(), result.errors.end(),
                                  [&](const FieldError& e) { return e.pointer == pointer; });
  if (found != result.errors.end()) return &*found;
  std::string got;
  for (const auto& e : result.errors)
    got += "\n  " + e.pointer + ": " + e.reason;
  ADD_FAILURE() << "no error at \"" << pointer << "\"; errors:" << got;
  return nullptr;
}

// Expects `job` to be refused with exactly one error, at `pointer`, whose reason contains
// `fragment`.
void expect_single_error(const json& job, const std::string& pointer, const std::string& fragment) {
  const ParseResult result = parse_job(job);
  EXPECT_FALSE(result.ok());
  EXPECT_FALSE(result.spec.has_value());
  ASSERT_EQ(result.errors.size(), 1u) << job.dump();
  if (const FieldError* e = error_at(result, pointer)) {
    EXPECT_NE(e->reason.find(fragment), std::string::npos) << e->reason;
  }
}

} // namespace

TEST(JobValidation, EmptyObjectIsThePaperScene) {
  const ParseResult result = parse_job(json::object());
  ASSERT_TRUE(result.ok());
  const auto& p = result.spec->params;
  EXPECT_DOUBLE_EQ(p.friction.L, 5e-5);
  EXPECT_DOUBLE_EQ(p.geometry.nodes_per_meter, 40.0);
  EXPECT_DOUBLE_EQ(p.loading.normal_stress, -0.0150);
  EXPECT_GT(result.spec->memory_estimate_bytes, 0.0);
  EXPECT_EQ(result.spec->sha256.size(), 64u);
}

TEST(JobValidation, EveryFieldIsMappedOntoParams) {
  const json job = json::parse(R"({
    "material": {"density": 2, "young_modulus": 3, "poisson_ratio": 0.3},
    "geometry": {"width": 20, "height": "auto", "x_min": -5, "nodes_per_meter": 10,
                 "top_boundary": "absorbing"},
    "loading": {"normal_stress": -0.02, "shear_stress": -0.01},
    "friction": {"law": "coulomb", "mu": 0.6, "L": 1e-4, "v_star": 2e-4,
                 "strength_update": "explicit_euler"},
    "nucleation": {"enabled": false, "a": 0.5, "b": 3, "v": 0.5, "alpha": 0.5},
    "time": {"duration": 8, "safety_factor": 0.4, "stop_on_arrest": false, "arrest_window": 2},
    "output": {"interval": 0.05, "space_stride": 2},
    "probe": {"arrival_x1": 5, "spectrum_x1": 3, "front_threshold": 1e-5},
    "threads": 2, "name": "all fields", "tags": ["a", "b"]
  })");
  const ParseResult result = parse_job(job);
  ASSERT_TRUE(result.ok()) << result.errors.front().pointer << ": " << result.errors.front().reason;
  const slipfront::api::JobSpec& spec = *result.spec;
  const slipfront::SimulationParams& p = spec.params;
  EXPECT_EQ(p.material.density, 2.0);
  EXPECT_EQ(p.material.young_modulus, 3.0);
  EXPECT_EQ(p.material.poisson_ratio, 0.3);
  EXPECT_EQ(p.geometry.width, 20.0);
  EXPECT_TRUE(p.geometry.auto_height);
  EXPECT_EQ(p.geometry.x_min, -5.0);
  EXPECT_EQ(p.geometry.nodes_per_meter, 10.0);
  EXPECT_EQ(p.top, slipfront::TopBoundary::absorbing);
  EXPECT_EQ(p.loading.normal_stress, -0.02);
  EXPECT_EQ(p.loading.shear_stress, -0.01);
  EXPECT_EQ(p.friction.law, "coulomb");
  EXPECT_EQ(p.friction.mu, 0.6);
  EXPECT_EQ(p.friction.L, 1e-4);
  EXPECT_EQ(p.friction.v_star, 2e-4);
  EXPECT_EQ(p.friction.update, slipfront::StrengthUpdate::explicit_euler);
  EXPECT_FALSE(p.nucleation.enabled);
  EXPECT_EQ(p.nucleation.a, 0.5);
  EXPECT_EQ(p.nucleation.b, 3.0);
  EXPECT_EQ(p.nucleation.v, 0.5);
  EXPECT_EQ(p.nucleation.alpha, 0.5);
  EXPECT_EQ(p.time.duration, 8.0);
  EXPECT_EQ(p.time.safety_factor, 0.4);
  EXPECT_FALSE(p.time.stop_on_arrest);
  EXPECT_EQ(p.time.arrest_window, 2.0);
  EXPECT_EQ(p.output.interval, 0.05);
  EXPECT_EQ(p.output.space_stride, 2);
  EXPECT_EQ(p.probes.arrival_x1, 5.0);
  EXPECT_EQ(p.probes.spectrum_x1, 3.0);
  EXPECT_EQ(p.probes.front_threshold, 1e-5);
  EXPECT_EQ(p.threads, 2);
  EXPECT_EQ(spec.name, "all fields");
  EXPECT_EQ(spec.tags, (std::vector<std::string>{"a", "b"}));
}

TEST(JobValidation, TopLevelMustBeAnObject) {
  for (const json& document : {json::array(), json(3), json("job"), json(nullptr)}) {
    const ParseResult result = parse_job(document);
    ASSERT_EQ(result.errors.size(), 1u);
    EXPECT_EQ(result.errors[0].pointer, "");
    EXPECT_NE(result.errors[0].reason.find("must be a JSON object"), std::string::npos);
  }
}

TEST(JobValidation, SyntaxErrorIsOneErrorAtTheRoot) {
  const ParseResult result = parse_job_text(R"({"friction": {"L": 1e-5,}})");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].pointer, "");
  EXPECT_NE(result.errors[0].reason.find("not valid JSON"), std::string::npos);
}

TEST(JobValidation, UnknownFieldsAtEveryLevel) {
  expect_single_error({{"frobnicate", 1}}, "/frobnicate", "unknown field");
  expect_single_error({{"friction", {{"foo", 1}}}}, "/friction/foo", "unknown field");
  expect_single_error({{"geometry", {{"depth", 1}}}}, "/geometry/depth", "unknown field");
  // The job's "nucleation" is not "nucleus"; the pointer escapes '/' and '~'.
  expect_single_error({{"nucleus", json::object()}}, "/nucleus", "unknown field");
  expect_single_error({{"a/b~c", 1}}, "/a~1b~0c", "unknown field");
}

TEST(JobValidation, UnknownFieldReasonListsTheKnownOnes) {
  const ParseResult result = parse_job({{"friction", {{"l", 1e-5}}}});
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_NE(result.errors[0].reason.find(
                "D_c, L, a, b, f0, initial_slip_rate, initial_state, law, mu, mu_d, mu_s, "
                "regularization, state_evolution, strength_update, t_star, theta, v_star"),
            std::string::npos)
      << result.errors[0].reason;
}

TEST(JobValidation, WrongTypesNameTheExpectedTypeAndTheValueGot) {
  expect_single_error({{"friction", {{"L", "small"}}}}, "/friction/L",
                      "must be a finite number > 0, got \"small\"");
  expect_single_error({{"material", {{"density", true}}}}, "/material/density",
                      "must be a finite number > 0, got true");
  expect_single_error({{"material", 3}}, "/material", "must be an object, got 3");
  expect_single_error({{"time", {{"stop_on_arrest", 1}}}}, "/time/stop_on_arrest",
                      "must be true or false, got 1");
  expect_single_error({{"nucleation", {{"enabled", "yes"}}}}, "/nucleation/enabled",
                      "must be true or false");
  expect_single_error({{"name", 42}}, "/name", "must be a string");
  expect_single_error({{"tags", "fast"}}, "/tags", "must be an array");
  expect_single_error({{"tags", {"ok", 3}}}, "/tags/1", "must be a non-empty string");
  expect_single_error({{"geometry", {{"width", nullptr}}}}, "/geometry/width", "got null");
  expect_single_error({{"probe", {{"arrival_x1", json::array()}}}}, "/probe/arrival_x1",
                      "got an array");
}

TEST(JobValidation, EnumerationsListTheirSpellings) {
  expect_single_error(
      {{"friction", {{"law", "dieterich"}}}}, "/friction/law",
      R"(must be one of "prakash_clifton", "coulomb", "slip_weakening", "rate_and_state", got "dieterich")");
  expect_single_error({{"friction", {{"strength_update", "rk4"}}}}, "/friction/strength_update",
                      R"("exponential_ramp", "exponential", "explicit_euler")");
  expect_single_error({{"geometry", {{"top_boundary", "free"}}}}, "/geometry/top_boundary",
                      R"("traction", "absorbing")");
}

// Found by the fuzzer (tests/fuzz/corpus/job_parser/regression-utf8-cut-in-error-message.json):
// the value shown in an error is cut to 40 bytes, and a cut inside a UTF-8 character made
// the message's dump() throw (a 500 from POST /jobs).
TEST(JobValidation, LongNonAsciiValueInAnErrorIsCutAtACharacter) {
  const std::string law =
      std::string(39, 'a') + "\u00e9\u00e9\u00e9"; // byte 40 is inside an e-acute
  ParseResult result;
  ASSERT_NO_THROW(result = parse_job({{"friction", {{"law", law}}}}));
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].pointer, "/friction/law");
  EXPECT_NE(result.errors[0].reason.find("got \"" + std::string(39, 'a') + "\"..."),
            std::string::npos)
      << result.errors[0].reason;
  ASSERT_NO_THROW(result = parse_job(json(law + law)));
  EXPECT_EQ(result.errors.size(), 1u);
}

TEST(JobValidation, MaterialRanges) {
  expect_single_error({{"material", {{"density", 0}}}}, "/material/density", "> 0, got 0");
  expect_single_error({{"material", {{"young_modulus", -2.5}}}}, "/material/young_modulus",
                      "> 0, got -2.5");
  expect_single_error({{"material", {{"poisson_ratio", 0.5}}}}, "/material/poisson_ratio",
                      "in (0, 0.5), got 0.5");
  expect_single_error({{"material", {{"poisson_ratio", 0}}}}, "/material/poisson_ratio",
                      "in (0, 0.5)");
  EXPECT_TRUE(parse_job({{"material", {{"poisson_ratio", 0.49}}}}).ok());
}

TEST(JobValidation, GeometryRanges) {
  expect_single_error({{"geometry", {{"width", 0}}}}, "/geometry/width", "> 0");
  expect_single_error({{"geometry", {{"height", -1}}}}, "/geometry/height",
                      R"(> 0 or "auto", got -1)");
  expect_single_error({{"geometry", {{"height", "tall"}}}}, "/geometry/height", R"("auto")");
  expect_single_error({{"geometry", {{"nodes_per_meter", -40}}}}, "/geometry/nodes_per_meter",
                      "> 0");
  expect_single_error({{"geometry", {{"x_min", "left"}}}}, "/geometry/x_min",
                      "must be a finite number, got");
}

TEST(JobValidation, NonFiniteNumbersAreRefused) {
  const double infinity = std::numeric_limits<double>::infinity();
  expect_single_error({{"geometry", {{"x_min", infinity}}}}, "/geometry/x_min",
                      "must be a finite number, got a non-finite number");
  expect_single_error({{"friction", {{"L", std::nan("")}}}}, "/friction/L", "non-finite");
  // In JSON text, 1e999 overflows in the parser: one error, naming the member.
  const ParseResult result = parse_job_text(R"({"geometry": {"x_min": 1e999}})");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].pointer, "/geometry/x_min");
  EXPECT_NE(result.errors[0].reason.find("overflow"), std::string::npos) << result.errors[0].reason;
}

TEST(JobValidation, MeshMustHoldWholeElements) {
  expect_single_error({{"geometry", {{"width", 40.01}}}}, "/geometry/width",
                      "whole number of elements");
  expect_single_error({{"geometry", {{"height", 20.01}}}}, "/geometry/height",
                      "whole number of elements");
  // 40 m * 10.05 nodes/m = 402 elements along x1, but 20 * 10.05 = 201 is fine too.
  EXPECT_TRUE(parse_job({{"geometry", {{"nodes_per_meter", 10.05}}}}).ok());
  // A product off by rounding noise only is accepted: 0.1 * 30 = 3.0000000000000004.
  EXPECT_TRUE(parse_job({{"geometry",
                          {{"width", 0.1}, {"height", 0.1}, {"nodes_per_meter", 30}, {"x_min", 0}}},
                         {"probe", {{"arrival_x1", 0.05}, {"spectrum_x1", 0.05}}},
                         {"nucleation", {{"enabled", false}}}})
                  .ok());
  expect_single_error({{"geometry", {{"width", 0.2}, {"nodes_per_meter", 10}, {"x_min", 0}}},
                       {"probe", {{"arrival_x1", 0.1}, {"spectrum_x1", 0.1}}}},
                      "/geometry/width", "need at least 3");
  // "auto" height is resolved by the solver: no whole-element rule on the JSON value.
  EXPECT_TRUE(parse_job({{"geometry", {{"height", "auto"}}}}).ok());
}

TEST(JobValidation, ElementCountsStayBounded) {
  expect_single_error({{"geometry", {{"nodes_per_meter", 1e6}, {"height", 1}}}},
                      "/geometry/nodes_per_meter", "more than the 10000000 allowed along one axis");
  // An absurd resolution makes both axes too long: one error, on the resolution, not on the
  // width and the height that are fine. 1e300 overflows the products. An
  // absurd length is blamed itself.
  for (const char* length : {"width", "height"}) {
    const ParseResult huge = parse_job({{"geometry", {{length, 1e300}}}});
    ASSERT_EQ(huge.errors.size(), 1u) << length;
    EXPECT_EQ(huge.errors[0].pointer, std::string("/geometry/") + length);
    EXPECT_NE(huge.errors[0].reason.find(std::string("use a smaller ") + length), std::string::npos)
        << huge.errors[0].reason;
  }
  for (const double nodes_per_meter : {1e9, 1e300}) {
    const ParseResult absurd = parse_job({{"geometry", {{"nodes_per_meter", nodes_per_meter}}}});
    ASSERT_EQ(absurd.errors.size(), 1u) << nodes_per_meter;
    EXPECT_EQ(absurd.errors[0].pointer, "/geometry/nodes_per_meter");
    EXPECT_NE(absurd.errors[0].reason.find("width * nodes_per_meter = 40 * "), std::string::npos)
        << absurd.errors[0].reason;
    EXPECT_NE(absurd.errors[0].reason.find("use fewer nodes per meter"), std::string::npos);
  }
  expect_single_error({{"geometry", {{"height", "auto"}}}, {"time", {{"duration", 1e9}}}},
                      "/geometry/height", "give a height or a shorter duration");
}

TEST(JobValidation, LoadingMustCompressAndStartStuck) {
  expect_single_error({{"loading", {{"normal_stress", 0.015}}}}, "/loading/normal_stress",
                      "< 0, got 0.015");
  expect_single_error({{"loading", {{"normal_stress", 0}}}}, "/loading/normal_stress", "< 0");
  // mu |p| = 0.75 * 0.015 = 0.01125 Pa: a larger shear load cannot start stuck.
  expect_single_error({{"loading", {{"shear_stress", 0.012}}}}, "/loading/shear_stress",
                      "static strength");
  expect_single_error({{"loading", {{"shear_stress", -0.012}}}}, "/loading/shear_stress",
                      "static strength");
  expect_single_error({{"friction", {{"mu", 0.5}}}}, "/loading/shear_stress", "static strength");
  EXPECT_TRUE(parse_job({{"loading", {{"shear_stress", -0.0105}}}}).ok());
}

TEST(JobValidation, FrictionRanges) {
  expect_single_error({{"friction", {{"mu", -0.1}}}}, "/friction/mu", ">= 0, got -0.1");
  expect_single_error({{"friction", {{"L", 0}}}}, "/friction/L", "> 0, got 0");
  expect_single_error({{"friction", {{"v_star", -1e-4}}}}, "/friction/v_star", "> 0");
  EXPECT_TRUE(parse_job({{"friction", {{"mu", 0}}}, {"loading", {{"shear_stress", 0}}}}).ok());
}

TEST(JobValidation, NucleationRanges) {
  expect_single_error({{"nucleation", {{"a", 0}}}}, "/nucleation/a", "> 0");
  expect_single_error({{"nucleation", {{"b", -3.6}}}}, "/nucleation/b", "> 0");
  expect_single_error({{"nucleation", {{"v", -0.825}}}}, "/nucleation/v", ">= 0");
  expect_single_error({{"nucleation", {{"alpha", 1.2}}}}, "/nucleation/alpha",
                      "in [0, 1], got 1.2");
  EXPECT_TRUE(parse_job({{"nucleation", {{"alpha", 0}}}}).ok());
  EXPECT_TRUE(parse_job({{"nucleation", {{"alpha", 1}}}}).ok());
}

TEST(JobValidation, TimeRanges) {
  expect_single_error({{"time", {{"duration", 0}}}}, "/time/duration", "> 0");
  expect_single_error({{"time", {{"safety_factor", 0}}}}, "/time/safety_factor", "in (0, 2]");
  expect_single_error({{"time", {{"safety_factor", 2.01}}}}, "/time/safety_factor", "in (0, 2]");
  expect_single_error({{"time", {{"arrest_window", -1}}}}, "/time/arrest_window", "> 0");
  EXPECT_TRUE(parse_job({{"time", {{"safety_factor", 1}}}}).ok());
}

TEST(JobValidation, OutputRanges) {
  expect_single_error({{"output", {{"interval", 0}}}}, "/output/interval", "> 0");
  expect_single_error({{"output", {{"space_stride", 0}}}}, "/output/space_stride",
                      "must be an integer in [1, ");
  expect_single_error({{"output", {{"space_stride", 1.5}}}}, "/output/space_stride", "got 1.5");
  expect_single_error({{"output", {{"space_stride", 1601}}}}, "/output/space_stride",
                      "number of interface nodes (1600)");
  // An integral float is an integer.
  const ParseResult result = parse_job({{"output", {{"space_stride", 4.0}}}});
  ASSERT_TRUE(result.ok());
  EXPECT_EQ(result.spec->params.output.space_stride, 4);
}

TEST(JobValidation, ProbesMustLieInTheDomain) {
  expect_single_error({{"probe", {{"arrival_x1", 30}}}}, "/probe/arrival_x1",
                      "[x_min, x_min + width) = [-10, 30), got 30");
  expect_single_error({{"probe", {{"spectrum_x1", -10.5}}}}, "/probe/spectrum_x1", "got -10.5");
  expect_single_error({{"probe", {{"front_threshold", 0}}}}, "/probe/front_threshold", "> 0");
  EXPECT_TRUE(parse_job({{"probe", {{"arrival_x1", -10}}}}).ok());
  // Moving the domain moves the allowed range.
  expect_single_error({{"geometry", {{"x_min", 0}}}, {"probe", {{"spectrum_x1", -1}}}},
                      "/probe/spectrum_x1", "[0, 40)");
}

TEST(JobValidation, ThreadsNameAndTags) {
  expect_single_error({{"threads", -1}}, "/threads", "integer in [0, 256], got -1");
  expect_single_error({{"threads", 257}}, "/threads", "got 257");
  expect_single_error({{"threads", "all"}}, "/threads", "got \"all\"");
  expect_single_error({{"name", std::string(300, 'x')}}, "/name", "at most 256 characters");
  expect_single_error({{"tags", {""}}}, "/tags/0", "non-empty");
  EXPECT_TRUE(parse_job({{"threads", 0}, {"tags", json::array()}}).ok());
}

TEST(JobValidation, AllErrorsAreReportedTogether) {
  const json job = json::parse(R"({
    "material": {"poisson_ratio": 0.5, "colour": "grey"},
    "friction": {"L": -1, "foo": 2, "law": "static"},
    "time": {"duration": "long"},
    "threads": 1000,
    "extra": true
  })");
  const ParseResult result = parse_job(job);
  EXPECT_EQ(result.errors.size(), 8u);
  for (const char* pointer :
       {"/material/poisson_ratio", "/material/colour", "/friction/L", "/friction/foo",
        "/friction/law", "/time/duration", "/threads", "/extra"}) {
    EXPECT_NE(error_at(result, pointer), nullptr);
  }
}

TEST(JobValidation, MemoryLimitRefusesHugeMeshes) {
  slipfront::api::ValidationLimits limits;
  limits.max_memory_bytes = 1e6;
  const ParseResult result = parse_job({{"geometry", {{"nodes_per_meter", 40}}}}, limits);
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].pointer, "/geometry/nodes_per_meter");
  EXPECT_NE(result.errors[0].reason.find("limit of 1 MB"), std::string::npos)
      << result.errors[0].reason;
  EXPECT_NE(result.errors[0].reason.find("MB of memory (estimate)"), std::string::npos);

  // The default limit accepts the paper's finest mesh ...
  EXPECT_TRUE(parse_job({{"geometry", {{"nodes_per_meter", 120}}}}).ok());
  // ... and refuses an absurd one.
  const ParseResult huge = parse_job({{"geometry", {{"nodes_per_meter", 4000}}}});
  ASSERT_FALSE(huge.ok());
  EXPECT_EQ(huge.errors[0].pointer, "/geometry/nodes_per_meter");
}

TEST(JobValidationMethod, MethodIsFeOrSpectralBi) {
  expect_single_error({{"method", "bem"}}, "/method", "\"fe\"");
  expect_single_error({{"method", 1}}, "/method", "spectral_bi");
  const ParseResult bi =
      parse_job({{"method", "spectral_bi"},
                 {"spectral_bi",
                  {{"time_step_factor", 0.25}, {"memory_periods", 16}, {"corrector_passes", 2}}}});
  ASSERT_TRUE(bi.ok());
  EXPECT_EQ(bi.spec->params.method, slipfront::Method::spectral_bi);
  EXPECT_EQ(bi.spec->params.spectral.time_step_factor, 0.25);
  EXPECT_EQ(bi.spec->params.spectral.memory_periods, 16.0);
  EXPECT_EQ(bi.spec->params.spectral.corrector_passes, 2);
}

TEST(JobValidationMethod, FieldsTheMethodDoesNotUseAreErrorsNamingTheField) {
  expect_single_error({{"method", "spectral_bi"}, {"geometry", {{"height", 20}}}},
                      "/geometry/height", "not used by method \"spectral_bi\"");
  expect_single_error({{"method", "spectral_bi"}, {"geometry", {{"top_boundary", "absorbing"}}}},
                      "/geometry/top_boundary", "not used by method \"spectral_bi\"");
  expect_single_error({{"method", "spectral_bi"}, {"time", {{"safety_factor", 0.5}}}},
                      "/time/safety_factor", "time_step_factor");
  expect_single_error({{"spectral_bi", {{"memory_periods", 8}}}}, "/spectral_bi",
                      "only with \"method\": \"spectral_bi\"");
  expect_single_error({{"method", "spectral_bi"}, {"fe", {{"mesh_damping", 0.5}}}}, "/fe",
                      "only with \"method\": \"fe\"");
}

// The perfectly matched layer's thickness is read with its top only, in [2, 1000] elements;
// the half-space has no top. A job without the layer keeps its canonical form (and hashes).
TEST(JobValidationMethod, PmlElementsAreReadWithThePmlTopOnly) {
  expect_single_error({{"geometry", {{"pml_elements", 10}}}}, "/geometry/pml_elements",
                      "only with top_boundary \"pml\"");
  expect_single_error({{"geometry", {{"top_boundary", "pml"}, {"pml_elements", 1}}}},
                      "/geometry/pml_elements", "[2, 1000]");
  expect_single_error({{"method", "spectral_bi"}, {"geometry", {{"pml_elements", 10}}}},
                      "/geometry/pml_elements", "not used by method \"spectral_bi\"");
  const ParseResult ok = parse_job({{"geometry", {{"top_boundary", "pml"}, {"pml_elements", 12}}}});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.spec->params.top, slipfront::TopBoundary::pml);
  EXPECT_EQ(ok.spec->params.geometry.pml_elements, 12);
  EXPECT_EQ(ok.spec->canonical["geometry"]["pml_elements"], 12);
  const ParseResult plain = parse_job({{"geometry", {{"top_boundary", "absorbing"}}}});
  ASSERT_TRUE(plain.ok());
  EXPECT_FALSE(plain.spec->canonical["geometry"].contains("pml_elements"));
}

TEST(JobValidationMethod, FeMeshDampingIsRangeChecked) {
  const ParseResult ok = parse_job({{"fe", {{"mesh_damping", 0.5}}}});
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(ok.spec->params.fe.mesh_damping, 0.5);
  EXPECT_EQ(parse_job(json::object()).spec->params.fe.mesh_damping, 0.0);
  expect_single_error({{"fe", {{"mesh_damping", -0.1}}}}, "/fe/mesh_damping", "[0, 4]");
  expect_single_error({{"fe", {{"mesh_damping", 5}}}}, "/fe/mesh_damping", "[0, 4]");
  expect_single_error({{"fe", {{"mesh_damping", "x"}}}}, "/fe/mesh_damping", "");
  expect_single_error({{"fe", {{"no_such_option", 1}}}}, "/fe/no_such_option", "");
}

TEST(JobValidationMethod, SpectralOptionsAreRangeChecked) {
  const json base = {{"method", "spectral_bi"}};
  json j = base;
  j["spectral_bi"] = {{"time_step_factor", 0}};
  expect_single_error(j, "/spectral_bi/time_step_factor", "(0, 0.75]");
  j["spectral_bi"] = {{"time_step_factor", 1.0}}; // diverges: refused up front
  expect_single_error(j, "/spectral_bi/time_step_factor", "(0, 0.75]");
  j["spectral_bi"] = {{"memory_periods", 1e9}};
  expect_single_error(j, "/spectral_bi/memory_periods", "(0, 256]");
  j["spectral_bi"] = {{"corrector_passes", 9}};
  expect_single_error(j, "/spectral_bi/corrector_passes", "");
  j["spectral_bi"] = {{"no_such_option", 1}};
  expect_single_error(j, "/spectral_bi/no_such_option", "");
}

TEST(JobValidationMethod, SpectralMemoryEstimateIsChecked) {
  // n_d = 2000 over 40 m: 80 000 nodes, ~1.1e7 lags of memory (~0.6 GB) is refused up
  // front under a 0.3 GB limit.
  slipfront::api::ValidationLimits limits;
  limits.max_memory_bytes = 3e8;
  const ParseResult r =
      parse_job({{"method", "spectral_bi"}, {"geometry", {{"nodes_per_meter", 2000}}}}, limits);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.errors[0].pointer, "/geometry/nodes_per_meter");
  const ParseResult small = parse_job({{"method", "spectral_bi"}}, limits);
  ASSERT_TRUE(small.ok());
  EXPECT_LT(small.spec->memory_estimate_bytes, 2e8);
}

// Nesting is bounded while parsing, before any recursive walk.
TEST(JobValidation, DeepNestingIsRefusedWhileParsing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const ParseResult result = parse_job_text(R"({"tags": )" + deep + "}");
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(result.errors[0].pointer.rfind("/tags/0/0", 0), 0u) << result.errors[0].pointer;
  EXPECT_NE(result.errors[0].reason.find("nests deeper than"), std::string::npos);
  // Syntax errors are told by position, not in the JSON library's words.
  const ParseResult syntax = parse_job_text("{\"a\": tru}");
  ASSERT_EQ(syntax.errors.size(), 1u);
  EXPECT_EQ(syntax.errors[0].reason.find("json.exception"), std::string::npos);
}

// The result file's size is estimated at validation and limited.
TEST(JobValidation, ResultSizeLimit) {
  const json tiny_interval = {{"output", {{"interval", 1e-6}}}, {"time", {{"duration", 3000.0}}}};
  EXPECT_TRUE(parse_job(tiny_interval).ok()) << "no limit by default (the CLI)";
  slipfront::api::ValidationLimits limits;
  limits.max_result_bytes = 20e9;
  const ParseResult refused = parse_job(tiny_interval, limits);
  ASSERT_EQ(refused.errors.size(), 1u);
  EXPECT_EQ(refused.errors[0].pointer, "/output/interval");
  EXPECT_NE(refused.errors[0].reason.find("result file would hold about"), std::string::npos);
  // The paper's job is far below the limit; its estimate bounds the real file (tens of MB).
  const ParseResult paper = parse_job(json::object(), limits);
  ASSERT_TRUE(paper.ok());
  EXPECT_GT(paper.spec->result_estimate_bytes, 1e6);
  EXPECT_LT(paper.spec->result_estimate_bytes, 1e9);
}
