// A job whose fields are each in range but which implies an impossible run
// (a step of 1e-302 s, 1e21 steps, an infinite wave speed, a run of 0 steps) is refused at
// validation, naming the field; the step count and the estimates never overflow.
#include "api/job_spec.hpp"
#include "api/run_bounds.hpp"
#include "solver/simulation.hpp"
#include "solver/spectral/mode_memory.hpp"
#include "solver/step_count.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using nlohmann::json;
using slipfront::api::parse_job;
using slipfront::api::ParseResult;

namespace {

// Expects exactly one error, at `pointer`, whose reason holds `fragment`.
void expect_refused(const json& job, const std::string& pointer, const std::string& fragment,
                    const slipfront::api::ValidationLimits& limits = {}) {
  const ParseResult r = parse_job(job, limits);
  ASSERT_EQ(r.errors.size(), 1u) << job.dump() << (r.ok() ? " was accepted" : "");
  EXPECT_EQ(r.errors[0].pointer, pointer) << job.dump() << ": " << r.errors[0].reason;
  EXPECT_NE(r.errors[0].reason.find(fragment), std::string::npos) << r.errors[0].reason;
}

json bi(json job) {
  job["method"] = "spectral_bi";
  return job;
}

} // namespace

TEST(RunBounds, TheInputsOfTheIssueAreRefusedNamingTheField) {
  // Each was answered 201; the first with a negative memory estimate, then "succeeded" with 0
  // steps and outcome no_rupture.
  expect_refused(bi({{"spectral_bi", {{"time_step_factor", 1e-300}}}}),
                 "/spectral_bi/time_step_factor", "time step would be 2.5e-302 s");
  for (const json& job :
       {json{{"time", {{"duration", 1e19}}}}, bi({{"time", {{"duration", 1e19}}}})})
    expect_refused(job, "/time/duration", "more than the limit 1e+09");
  for (const json& job : {json{{"material", {{"young_modulus", 1e300}}}},
                          bi({{"material", {{"young_modulus", 1e300}}}})})
    expect_refused(job, "/material/young_modulus", "less than the limit 1e-100 s");
  for (const json& job :
       {json{{"material", {{"density", 5e-324}}}}, bi({{"material", {{"density", 5e-324}}}})})
    expect_refused(job, "/material/density", "must be finite and > 0");
  for (const json& job :
       {json{{"material", {{"density", 1.7e308}}}}, bi({{"material", {{"density", 1.79e308}}}})})
    expect_refused(job, "/material/density", "shorter than one time step");
}

TEST(RunBounds, TheStepLimitNamesTheFieldThatMovesTheCountFurthest) {
  expect_refused(bi({{"spectral_bi", {{"time_step_factor", 1e-10}}}}),
                 "/spectral_bi/time_step_factor", "the run would take 6.4e+12 time steps");
  expect_refused({{"time", {{"duration", 1e300}}}}, "/time/duration", "up to 2.77e+302");
  // Each alone is fine; together they pass the limit, and the duration moved furthest.
  // (Under a memory limit that lets the probe records of 1e9 steps through.)
  const slipfront::api::ValidationLimits roomy{.max_memory_bytes = 1e12};
  EXPECT_TRUE(parse_job({{"time", {{"duration", 2e6}}}}, roomy).ok());
  EXPECT_TRUE(parse_job({{"geometry", {{"nodes_per_meter", 100}}}}, roomy).ok());
  expect_refused({{"time", {{"duration", 2e6}}}, {"geometry", {{"nodes_per_meter", 100}}}},
                 "/time/duration", "more than the limit", roomy);
  expect_refused({{"material", {{"poisson_ratio", 0.49999999999999994}}}},
                 "/material/poisson_ratio", "time steps");
  expect_refused({{"time", {{"duration", 1e-30}}}}, "/time/duration",
                 "the run would simulate nothing");
}

TEST(RunBounds, SpectralKernelNeedsABoundedWaveSpeedRatio) {
  expect_refused(bi({{"material", {{"poisson_ratio", 0.4999999}}}}), "/material/poisson_ratio",
                 "c_p / c_s = 2.24e+03");
  EXPECT_TRUE(parse_job(bi({{"material", {{"poisson_ratio", 0.49}}}})).ok());
}

TEST(RunBounds, OrdinaryAndLargeButPossibleJobsStayAccepted) {
  for (const json& job : {json::object(), bi(json::object()),
                          json{{"material", {{"density", 1e300}, {"young_modulus", 1e300}}}},
                          json{{"material", {{"density", 7800}, {"young_modulus", 2e11}}},
                               {"time", {{"duration", 1e-3}}}},
                          json{{"time", {{"duration", 3000}}}}})
    EXPECT_TRUE(parse_job(job).ok()) << job.dump() << ": " << parse_job(job).errors[0].reason;
}

TEST(RunBounds, FeTimeStepLiesWithinItsBounds) {
  // The bounds the validation uses hold the step the run takes (power iteration).
  for (double nu : {0.1, 0.25, 0.45}) {
    for (double damping : {0.0, 1.0}) {
      slipfront::SimulationParams p;
      p.geometry = {.width = 4, .height = 2, .x_min = -2, .nodes_per_meter = 5};
      p.material.poisson_ratio = nu;
      p.fe.mesh_damping = damping;
      p.time.duration = 0.5;
      p.probes.arrival_x1 = p.probes.spectrum_x1 = 1.0;
      const auto bounds = slipfront::time_step_bounds(p);
      const double dt = slipfront::run_simulation(p).metrics.dt;
      EXPECT_GE(dt, bounds.shortest) << "nu " << nu << " damping " << damping;
      EXPECT_LE(dt, bounds.longest * (1 + 1e-9)) << "nu " << nu << " damping " << damping;
    }
  }
}

TEST(RunBounds, EstimatesAreFiniteAndPositiveForEveryAcceptedExtreme) {
  // Every numeric input at extremes of its range, alone: refused, or estimated as a finite,
  // positive size within the limits (before the fix: -9.2e18 bytes for 1e-300).
  const std::vector<std::pair<std::string, std::string>> fields = {
      {"material", "density"},
      {"material", "young_modulus"},
      {"material", "poisson_ratio"},
      {"geometry", "nodes_per_meter"},
      {"time", "duration"},
      {"output", "interval"},
      {"spectral_bi", "time_step_factor"},
      {"spectral_bi", "memory_periods"},
      {"time", "safety_factor"},
      {"fe", "mesh_damping"}};
  const double values[] = {5e-324, 1e-300, 1e-30, 1e-9, 0.4999, 0.7,    1.9,
                           3.9,    256,    1e9,   1e30, 1e300,  1.7e308};
  slipfront::api::ValidationLimits limits;
  limits.max_result_bytes = 1e12;
  int accepted = 0, refused = 0;
  for (const auto& [section, key] : fields) {
    for (double value : values) {
      json job = {{section, {{key, value}}}};
      if (section == "spectral_bi") job["method"] = "spectral_bi";
      const ParseResult r = parse_job(job, limits);
      if (!r.ok()) {
        ++refused;
        continue;
      }
      ++accepted;
      EXPECT_TRUE(std::isfinite(r.spec->memory_estimate_bytes)) << job.dump();
      EXPECT_GT(r.spec->memory_estimate_bytes, 0.0) << job.dump();
      EXPECT_LE(r.spec->memory_estimate_bytes, limits.max_memory_bytes) << job.dump();
      EXPECT_TRUE(std::isfinite(r.spec->result_estimate_bytes)) << job.dump();
      EXPECT_GT(r.spec->result_estimate_bytes, 0.0) << job.dump();
      EXPECT_LE(slipfront::step_count_bound(r.spec->params), slipfront::max_run_steps);
    }
  }
  EXPECT_GT(accepted, 10);
  EXPECT_GT(refused, 10);
}

TEST(StepCount, CountsAreCheckedBeforeTheyBecomeIntegers) {
  EXPECT_EQ(slipfront::checked_step_count(slipfront::steps_to_reach(16.0, 0.01)), 1600);
  // A duration far below one step takes none: what the validation refuses.
  EXPECT_EQ(slipfront::checked_step_count(slipfront::steps_to_reach(1e-30, 0.01)), 0);
  const double inf = std::numeric_limits<double>::infinity();
  for (double steps : {1e302, inf, -inf / inf, -1.0, slipfront::max_run_steps + 1})
    EXPECT_THROW(slipfront::checked_step_count(steps), std::invalid_argument) << steps;
  EXPECT_EQ(slipfront::steps_per_interval(0.02, 0.01), 2);
  EXPECT_EQ(slipfront::steps_per_interval(1e-9, 0.01), 1);
  EXPECT_EQ(slipfront::steps_per_interval(1e300, 1e-300), int(slipfront::max_run_steps));
  // A mode's memory window of 1e30 steps is clamped to the run, not converted first.
  EXPECT_EQ(slipfront::spectral::ModeMemory::memory_length(1, 40.0, 1e-30, 1.0, 8.0, 5000), 5000);
}
