// The job's "stations" section: its validation (errors named by JSON pointer), its place in the
// canonical form and the hashes (absent or empty: nothing changes), and its cost in the
// memory, result-size and run bounds.
#include "api/job_schema.hpp"
#include "api/job_spec.hpp"
#include "api/run_bounds.hpp"

#include <gtest/gtest.h>

#include <algorithm>

using nlohmann::json;
using slipfront::api::FieldError;
using slipfront::api::parse_job;
using slipfront::api::ParseResult;

namespace {

// The reason of the error at `pointer` ("" and a test failure listing the errors if none).
std::string reason_at(const ParseResult& result, const std::string& pointer) {
  for (const FieldError& e : result.errors)
    if (e.pointer == pointer) return e.reason;
  std::string got;
  for (const FieldError& e : result.errors)
    got += "\n  " + e.pointer + ": " + e.reason;
  ADD_FAILURE() << "no error at " << pointer << "; errors:" << got;
  return "";
}

json with_stations(json job, const json& stations) {
  job["stations"] = stations;
  return job;
}

slipfront::api::JobSpec parsed(const json& job) {
  const ParseResult result = parse_job(job);
  if (!result.ok()) {
    ADD_FAILURE() << result.errors.front().pointer << ": " << result.errors.front().reason;
    return {};
  }
  return *result.spec;
}

} // namespace

TEST(StationsSpec, PositionsAndThresholdReachTheParameters) {
  const auto spec = parsed({{"stations", {{"x1", {0, 4.5, -10}}, {"rupture_threshold", 2e-3}}}});
  EXPECT_EQ(spec.params.stations.x1, (std::vector<double>{0.0, 4.5, -10.0}));
  EXPECT_EQ(spec.params.stations.rupture_threshold, 2e-3);
  EXPECT_EQ(spec.canonical["stations"], json::parse(R"({"x1": [0, 4.5, -10],
                                                        "rupture_threshold": 0.002})"));
  const auto defaults = parsed({{"stations", {{"x1", {1}}}}});
  // One threshold: the front's, unless the job gives the stations their own.
  EXPECT_EQ(defaults.params.stations.rupture_threshold, defaults.params.probes.front_threshold);
  EXPECT_TRUE(parsed(json::object()).params.stations.x1.empty());
}

TEST(StationsSpec, EachStationMustLieInTheDomain) {
  // The paper's domain: [-10, 30).
  const ParseResult result = parse_job({{"stations", {{"x1", {0, 29.9, -10, 30, -10.5}}}}});
  EXPECT_EQ(result.errors.size(), 2u);
  EXPECT_EQ(reason_at(result, "/stations/x1/3"),
            "must lie in the domain [x_min, x_min + width) = [-10, 30), got 30");
  EXPECT_NE(reason_at(result, "/stations/x1/4").find("got -10.5"), std::string::npos);
}

TEST(StationsSpec, TheDomainIsTheJobsOwn) {
  const json geometry = {{"x_min", -50}, {"width", 100}, {"nodes_per_meter", 1}};
  EXPECT_TRUE(parse_job({{"geometry", geometry}, {"stations", {{"x1", {-50, 45}}}}}).ok());
  const ParseResult result = parse_job({{"geometry", geometry}, {"stations", {{"x1", {-50, 50}}}}});
  EXPECT_NE(reason_at(result, "/stations/x1/1").find("[-50, 50)"), std::string::npos);
}

TEST(StationsSpec, TypesAndCountsAreChecked) {
  ParseResult result = parse_job({{"stations", {{"x1", {1, "two", nullptr, true}}}}});
  EXPECT_EQ(result.errors.size(), 3u);
  EXPECT_EQ(reason_at(result, "/stations/x1/1"), "must be a finite number, got \"two\"");
  EXPECT_EQ(reason_at(result, "/stations/x1/2"), "must be a finite number, got null");
  EXPECT_EQ(reason_at(result, "/stations/x1/3"), "must be a finite number, got true");

  result = parse_job({{"stations", {{"x1", 4.5}}}});
  EXPECT_EQ(reason_at(result, "/stations/x1"), "must be an array of at most 64 numbers, got 4.5");
  result = parse_job({{"stations", {{"x1", std::vector<double>(65, 1.0)}}}});
  EXPECT_EQ(reason_at(result, "/stations/x1"),
            "must be an array of at most 64 numbers, got 65 items");
  std::vector<double> many(64);
  for (int i = 0; i < 64; ++i)
    many[i] = -10.0 + 0.5 * i;
  EXPECT_TRUE(parse_job({{"stations", {{"x1", many}}}}).ok());

  result = parse_job({{"stations", {{"x1", {1}}, {"rupture_threshold", 0}}}});
  EXPECT_EQ(reason_at(result, "/stations/rupture_threshold"), "must be a finite number > 0, got 0");
  result = parse_job({{"stations", {{"x1", {1}}, {"where", 1}}}});
  EXPECT_NE(reason_at(result, "/stations/where").find("unknown field"), std::string::npos);
  result = parse_job({{"stations", {1, 2}}});
  EXPECT_EQ(reason_at(result, "/stations"), "must be an object, got an array");
}

TEST(StationsSpec, AStationIsListedOnce) {
  const ParseResult result = parse_job({{"stations", {{"x1", {1, 2, 1.0}}}}});
  ASSERT_EQ(result.errors.size(), 1u);
  EXPECT_EQ(reason_at(result, "/stations/x1/2"), "repeats station 0 (x1 = 1): each station once");
}

TEST(StationsSpec, NoStationsLeaveTheCanonicalFormAndTheHashesAlone) {
  for (const json& base : {json::object(), json{{"method", "spectral_bi"}},
                           json{{"friction", {{"L", 1e-5}}}, {"geometry", {{"width", 30}}}}}) {
    const auto plain = parsed(base);
    EXPECT_FALSE(plain.canonical.contains("stations"));
    for (const json& empty : {json::object(), json{{"x1", json::array()}},
                              json{{"x1", json::array()}, {"rupture_threshold", 0.01}}}) {
      const auto same = parsed(with_stations(base, empty));
      EXPECT_EQ(same.canonical, plain.canonical) << empty.dump();
      EXPECT_EQ(same.sha256, plain.sha256);
      EXPECT_EQ(slipfront::api::scene_hash(same.canonical),
                slipfront::api::scene_hash(plain.canonical));
    }
  }
}

TEST(StationsSpec, StationsChangeTheSpecHashButNotTheScene) {
  // A result with stations carries their records and rupture times: not the cached result of a
  // job without. The scene (what a convergence map groups) is the same physics.
  const auto plain = parsed(json::object());
  const auto one = parsed({{"stations", {{"x1", {4.5}}}}});
  const auto other = parsed({{"stations", {{"x1", {4.5}}, {"rupture_threshold", 1e-2}}}});
  EXPECT_NE(one.sha256, plain.sha256);
  EXPECT_NE(other.sha256, one.sha256);
  EXPECT_EQ(slipfront::api::scene_hash(one.canonical), slipfront::api::scene_hash(plain.canonical));
  EXPECT_EQ(slipfront::api::counterpart_scene_hash(one.canonical),
            slipfront::api::counterpart_scene_hash(plain.canonical));
}

TEST(StationsSpec, RecordsCountInTheMemoryAndResultEstimates) {
  const auto plain = parsed({{"method", "spectral_bi"}});
  const auto four = parsed({{"method", "spectral_bi"}, {"stations", {{"x1", {0, 1, 2, 3}}}}});
  // BI's step bound: 16 s / (dt = 0.5 dx / c_s = 0.0125 s) = 1280 steps, plus one.
  const double steps = 1281.0;
  // Every step: the time and 4 series x 4 stations; per station: its nodes, weights and
  // rupture time.
  const double series = 8.0 * steps * (1.0 + 4.0 * 4.0) + 8.0 * 5.0 * 4.0;
  EXPECT_NEAR(four.memory_estimate_bytes - plain.memory_estimate_bytes, series, 1e-6 * series);
  EXPECT_NEAR(four.result_estimate_bytes - plain.result_estimate_bytes, series, 1e-6 * series);
}

TEST(StationsSpec, TheStationRecordIsBounded) {
  // 64 stations every step of a long, fine BI run: more than the station record may hold.
  std::vector<double> many(64);
  for (int i = 0; i < 64; ++i)
    many[i] = -10.0 + 0.5 * i;
  const json job = {
      {"method", "spectral_bi"}, {"time", {{"duration", 3000}}}, {"stations", {{"x1", many}}}};
  const ParseResult result = parse_job(job, {.max_memory_bytes = 1e12});
  ASSERT_EQ(result.errors.size(), 1u);
  const std::string reason = reason_at(result, "/stations/x1");
  EXPECT_NE(reason.find("the 64 stations would record"), std::string::npos) << reason;
  EXPECT_NE(reason.find("fewer stations or a shorter duration"), std::string::npos) << reason;
  // The same run with one station stays below the bound.
  EXPECT_TRUE(parse_job(with_stations(job, {{"x1", {0}}}), {.max_memory_bytes = 1e12}).ok());
}

TEST(StationsSpec, SchemaOffersAnArrayOfNumbers) {
  const json schema = slipfront::api::job_json_schema();
  const json& stations = schema["properties"]["stations"];
  EXPECT_EQ(stations["additionalProperties"], false);
  const json& x1 = stations["properties"]["x1"];
  EXPECT_EQ(x1["type"], "array");
  EXPECT_EQ(x1["maxItems"], 64);
  EXPECT_EQ(x1["items"]["type"], "number");
  EXPECT_EQ(x1["default"], json::array());
  EXPECT_EQ(x1["x-unit"], "m");
  EXPECT_EQ(x1["x-methods"], json({"fe", "spectral_bi"}));
  EXPECT_EQ(stations["properties"]["rupture_threshold"]["default"], 1e-6);
  EXPECT_EQ(stations["properties"]["rupture_threshold"]["exclusiveMinimum"], 0);
  const std::string markdown = slipfront::api::job_fields_markdown();
  EXPECT_NE(markdown.find("| `x1` | array of numbers | `[]` | at most 64 numbers |"),
            std::string::npos);
}
