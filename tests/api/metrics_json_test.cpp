// The metrics JSON: the names of docs/metrics.md, null for undefined values, the method that ran.
#include "api/metrics_reader.hpp"
#include "api/metrics_row.hpp"
#include "api/run_job.hpp"
#include "synthetic_run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

using nlohmann::json;
using slipfront::api::front_json;
using slipfront::api::method_description;
using slipfront::api::metrics_json;

namespace {

slipfront::RunResult example_result() {
  slipfront::RunResult result =
      slipfront::testing::synthetic_result(slipfront::testing::synthetic_layout(4));
  auto& m = result.metrics;
  m.front_threshold = 1e-6;
  m.arrest_position = 12.5;
  m.propagation_distance = 12.4;
  m.arrival_time_at_probe = std::numeric_limits<double>::quiet_NaN();
  m.probe_x1 = 11.0;
  m.max_rupture_speed = 1.6;
  m.mean_rupture_speed = 1.2;
  m.max_slip_velocity = 8e-3;
  m.outcome = slipfront::Outcome::arrested;
  m.energy_error = 1e-4;
  m.spectral_frequency = 2.0;
  m.spectral_velocity = 1e-3;
  m.spectral_critical_length = 1e-5;
  m.wall_time_s = 3.5;
  m.steps = 1234;
  m.dt = 0.05;
  m.simulated_time = 12.0;
  m.warnings = {"energy error above 1 %"};
  m.message = "arrested at t = 12 s";
  return result;
}

} // namespace

// The metrics row the server stores is read from the metrics JSON, whichever runner ran the
// job (a local worker, or a SLURM job's report): every column the solver's value, undefined
// values unset.
TEST(MetricsRow, FromTheMetricsJsonHoldsTheSolverValues) {
  const slipfront::RunResult result = example_result();
  const auto row = slipfront::api::metrics_row(metrics_json(result));
  EXPECT_EQ(row.arrest_position, std::optional<double>(12.5));
  EXPECT_EQ(row.propagation_distance, std::optional<double>(12.4));
  EXPECT_FALSE(row.arrival_time_at_probe) << "NaN: the front never reached the probe";
  EXPECT_EQ(row.max_rupture_speed, std::optional<double>(1.6));
  EXPECT_EQ(row.mean_rupture_speed, std::optional<double>(1.2));
  EXPECT_EQ(row.max_slip_velocity, std::optional<double>(8e-3));
  EXPECT_EQ(row.outcome, std::optional<std::string>("arrested"));
  EXPECT_EQ(row.energy_error, std::optional<double>(1e-4));
  EXPECT_EQ(row.wall_time_s, std::optional<double>(3.5));
  EXPECT_EQ(row.steps, std::optional<std::int64_t>(1234));
  EXPECT_EQ(row.dt, std::optional<double>(0.05));
  EXPECT_EQ(row.simulated_time, std::optional<double>(12.0));
}

TEST(MetricsJson, HoldsEverySpecMetricByName) {
  const json j = metrics_json(example_result());
  for (const char* name : {"front_threshold",
                           "arrest_position",
                           "propagation_distance",
                           "arrival_time_at_probe",
                           "rupture_speed",
                           "max_slip_velocity",
                           "outcome",
                           "energy_error",
                           "wall_time_s",
                           "steps",
                           "dt",
                           "stable_dt",
                           "simulated_time",
                           "spectral_critical_length",
                           "spectral_frequency",
                           "spectral_velocity",
                           "warnings",
                           "message",
                           "mesh",
                           "code_version",
                           "method",
                           "method_description"}) {
    EXPECT_TRUE(j.contains(name)) << name;
  }
  EXPECT_EQ(j["arrest_position"], 12.5);
  EXPECT_EQ(j["propagation_distance"], 12.4);
  EXPECT_EQ(j["rupture_speed"], json({{"max", 1.6}, {"mean", 1.2}}));
  EXPECT_EQ(j["max_slip_velocity"], 8e-3);
  EXPECT_EQ(j["outcome"], "arrested");
  EXPECT_EQ(j["steps"], 1234);
  EXPECT_EQ(j["dt"], 0.05);
  EXPECT_EQ(j["stable_dt"], 0.1);
  EXPECT_EQ(j["warnings"], json({"energy error above 1 %"}));
  EXPECT_EQ(j["message"], "arrested at t = 12 s");
  EXPECT_EQ(j["mesh"], json({{"nx", 4}, {"ny", 3}, {"dx", 0.25}, {"height", 0.5}, {"threads", 1}}));
  EXPECT_EQ(j["code_version"], slipfront::code_version());
}

// With an elastic lower solid (FE) the mesh also gives the lower block's rows and height.
TEST(MetricsJson, MeshNamesTheLowerBlock) {
  slipfront::RunResult result = example_result();
  result.mesh.lower_ny = 5;
  result.mesh.lower_height = 1.0;
  EXPECT_EQ(metrics_json(result)["mesh"], json({{"nx", 4},
                                                {"ny", 3},
                                                {"dx", 0.25},
                                                {"height", 0.5},
                                                {"threads", 1},
                                                {"lower_ny", 5},
                                                {"lower_height", 1.0}}));
  slipfront::SimulationParams params;
  params.lower.side = slipfront::LowerSide::elastic;
  params.lower.bottom = slipfront::TopBoundary::absorbing;
  EXPECT_EQ(method_description(params),
            "Q4 2x2 Gauss, lumped mass, central differences; top boundary: traction; lower "
            "solid: elastic block (split-node interface), bottom boundary: absorbing; "
            "friction: prakash_clifton, exponential_ramp strength update");
}

TEST(MetricsJson, UndefinedValuesAreNull) {
  const json j = metrics_json(example_result());
  EXPECT_TRUE(j["arrival_time_at_probe"].is_null());
  // The text is valid JSON (no NaN literal) and parses back equal.
  EXPECT_EQ(json::parse(j.dump()), j);
}

TEST(MetricsJson, EveryOutcomeHasItsSpecName) {
  slipfront::RunResult result = example_result();
  const std::vector<std::pair<slipfront::Outcome, std::string>> outcomes = {
      {slipfront::Outcome::arrested, "arrested"},
      {slipfront::Outcome::running_at_end, "running_at_end"},
      {slipfront::Outcome::no_rupture, "no_rupture"},
      {slipfront::Outcome::diverged, "diverged"}};
  for (const auto& [outcome, name] : outcomes) {
    result.metrics.outcome = outcome;
    EXPECT_EQ(metrics_json(result)["outcome"], name);
  }
}

TEST(MetricsJson, MethodNamesDiscretisationBoundaryAndFriction) {
  slipfront::SimulationParams params;
  EXPECT_EQ(method_description(params),
            "Q4 2x2 Gauss, lumped mass, central differences; top boundary: traction; "
            "friction: prakash_clifton, exponential_ramp strength update");
  params.friction.update = slipfront::StrengthUpdate::exponential;
  EXPECT_EQ(method_description(params),
            "Q4 2x2 Gauss, lumped mass, central differences; top boundary: traction; "
            "friction: prakash_clifton, exponential strength update");
  params.top = slipfront::TopBoundary::absorbing;
  params.friction.law = "coulomb";
  EXPECT_EQ(method_description(params),
            "Q4 2x2 Gauss, lumped mass, central differences; top boundary: absorbing; "
            "friction: coulomb");
  EXPECT_EQ(metrics_json(example_result(), params)["method_description"],
            method_description(params));
  EXPECT_EQ(metrics_json(example_result(), params)["method"], "fe");
  EXPECT_EQ(metrics_json(example_result())["method_description"],
            "Q4 2x2 Gauss, lumped mass, central differences");
  params.method = slipfront::Method::spectral_bi;
  EXPECT_EQ(metrics_json(example_result(), params)["method"], "spectral_bi");
  EXPECT_EQ(method_description(params),
            "spectral boundary integral, elastic half-space (velocity-form memory truncated "
            "after 8 mode periods), dt = 0.5 dx / c_s, 1 corrector pass; friction: coulomb");
  params.lower.side = slipfront::LowerSide::elastic;
  EXPECT_EQ(method_description(params),
            "spectral boundary integral, two elastic half-spaces (velocity-form memory truncated "
            "after 8 mode periods), dt = 0.5 dx / max c_s, 1 corrector pass; friction: coulomb");
}

TEST(FrontJson, ArraysWithNullWhereUndefined) {
  const json j = front_json(example_result());
  ASSERT_EQ(j["x1"].size(), 4u);
  EXPECT_EQ(j["x1"][1], -9.75);
  EXPECT_TRUE(j["arrival_time"][0].is_null());
  EXPECT_EQ(j["arrival_time"][1], 0.5);
  EXPECT_TRUE(j["rupture_speed"][3].is_null());
  EXPECT_EQ(j["rupture_speed"][2], 1.5);
}

// Metrics of an imported run (api/metrics_reader.hpp): what metrics_json() writes reads back
// whole; other names are dropped, a value of the wrong kind is named.
TEST(MetricsReader, WhatMetricsJsonWritesReadsBackWhole) {
  slipfront::RunResult result = example_result();
  result.stations.x1 = {4.5, 6.0};
  result.stations.rupture_time = {3.6, std::numeric_limits<double>::quiet_NaN()};
  const json written = metrics_json(result);
  const auto read = slipfront::api::read_metrics(written);
  EXPECT_TRUE(read.errors.empty()) << read.errors.front().pointer;
  EXPECT_TRUE(read.dropped.empty()) << read.dropped.front();
  EXPECT_EQ(read.metrics, written);
  const auto& names = slipfront::api::metric_names();
  for (const auto& [name, value] : written.items())
    EXPECT_NE(std::find(names.begin(), names.end(), name), names.end()) << name;
}

TEST(MetricsReader, UnknownNamesAreDroppedAndBadValuesNamed) {
  json metrics = metrics_json(example_result());
  metrics["column_17"] = 1.0;
  metrics["steps"] = 1e300;
  metrics["outcome"] = 3;
  metrics["mesh"]["nx"] = "many";
  const auto read = slipfront::api::read_metrics(metrics);
  EXPECT_EQ(read.dropped, std::vector<std::string>{"column_17"});
  std::vector<std::string> pointers;
  for (const auto& e : read.errors)
    pointers.push_back(e.pointer);
  EXPECT_EQ(pointers, (std::vector<std::string>{"/mesh", "/outcome", "/steps"}));
  EXPECT_FALSE(read.metrics.contains("column_17"));
  // The metrics row never converts such a count to an integer.
  EXPECT_FALSE(slipfront::api::metrics_row({{"steps", 1e300}}).steps.has_value());
  EXPECT_FALSE(slipfront::api::metrics_row({{"steps", 2.5}}).steps.has_value());
  EXPECT_EQ(slipfront::api::metrics_row({{"steps", 552}}).steps, 552);
}
