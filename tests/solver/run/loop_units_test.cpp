// The units of the time loop (solver/run/time_loop.cpp), each on its own: front tracking,
// probe, energy and interface sampling, the divergence check, the arrest rule, progress.
#include "verification_support.hpp"

#include "solver/interface/nucleation.hpp"
#include "solver/run/arrest_rule.hpp"
#include "solver/run/divergence_check.hpp"
#include "solver/run/energy_recorder.hpp"
#include "solver/run/front_tracker.hpp"
#include "solver/run/interface_sampler.hpp"
#include "solver/run/probe_recorder.hpp"
#include "solver/run/progress_reporter.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <limits>
#include <thread>

namespace slipfront {
namespace {

// n nodes at x1 = i dx, at rest, with the paper's initial pressure and strength.
InterfaceFields resting_interface(int n, double dx, double p0 = 3e6, double mu = 0.75) {
  InterfaceFields f;
  for (int i = 0; i < n; ++i)
    f.x1.push_back(i * dx);
  f.velocity.assign(n, 0.0);
  f.half_velocity.assign(n, 0.0);
  f.slip.assign(n, 0.0);
  f.opening.assign(n, 0.0);
  f.shear_traction.assign(n, 0.0);
  f.pressure.assign(n, p0);
  f.strength.assign(n, mu * p0);
  f.state.assign(n, std::int8_t(NodeState::stick));
  return f;
}

TEST(FrontTracker, InterpolatesTheCrossingBetweenHalfSteps) {
  FrontTracker front(3, 1e-3);
  EXPECT_TRUE(std::isinf(front.last_new_arrival()));
  const double dt = 0.1;
  front.update({0.0, 0.5e-3, 0.0}, 0.05, dt); // below the threshold everywhere
  EXPECT_TRUE(std::isnan(front.arrival()[1]));
  front.update({0.0, 1.5e-3, -4e-3}, 0.15, dt); // node 1 halfway, node 2 a quarter
  EXPECT_DOUBLE_EQ(front.arrival()[1], 0.05 + 0.5 * dt);
  EXPECT_DOUBLE_EQ(front.arrival()[2], 0.05 + 0.25 * dt);
  EXPECT_TRUE(std::isnan(front.arrival()[0]));
  EXPECT_DOUBLE_EQ(front.last_new_arrival(), 0.05 + 0.5 * dt);
  front.update({0.0, 0.0, 0.0}, 0.25, dt); // the first arrival is kept
  EXPECT_DOUBLE_EQ(front.arrival()[1], 0.05 + 0.5 * dt);
}

TEST(FrontTracker, NoArrivalBeforeTimeZero) {
  FrontTracker front(1, 1e-3);
  front.update({1.0}, 0.5e-3, 1e-3); // v^{-1/2} = 0 sits at -dt/2
  EXPECT_EQ(front.arrival()[0], 0.0);
}

TEST(ProbeRecorder, RecordsAtTheNearestNodesEachStep) {
  InterfaceFields f = resting_interface(10, 0.5);
  Probes probes;
  probes.arrival_x1 = 2.2;  // nearest node 4 (x1 = 2.0)
  probes.spectrum_x1 = 4.8; // nearest node 10 -> wraps to node 0
  ProbeRecorder rec(probes, 0.0, 0.5, f.x1);
  f.velocity[4] = 1.5;
  f.velocity[0] = -2.5;
  f.strength[0] = 7.0;
  rec.record(f, 0.25);
  const ProbeRecords r = rec.take();
  EXPECT_EQ(r.arrival_node_x1, 2.0);
  EXPECT_EQ(r.spectrum_node_x1, 0.0);
  ASSERT_EQ(r.time.size(), 1u);
  EXPECT_EQ(r.time[0], 0.25);
  EXPECT_EQ(r.slip_velocity_arrival[0], 1.5);
  EXPECT_EQ(r.slip_velocity_spectrum[0], -2.5);
  EXPECT_EQ(r.strength_spectrum[0], 7.0);
}

TEST(EnergyRecorder, DueEveryFiftyMillisecondsAndStampedAtTheHalfStep) {
  EnergyRecorder rec(0.01); // every 5 steps
  EXPECT_TRUE(rec.due(0));
  EXPECT_FALSE(rec.due(4));
  EXPECT_TRUE(rec.due(5));
  EnergyBalance e{1, 2, 3, 4};
  rec.record(e, 0.05);
  const EnergyRecords r = rec.take();
  ASSERT_EQ(r.time.size(), 1u);
  EXPECT_DOUBLE_EQ(r.time[0], 0.055);
  EXPECT_EQ(r.kinetic[0], 1);
  EXPECT_EQ(r.strain[0], 2);
  EXPECT_EQ(r.external_work[0], 3);
  EXPECT_EQ(r.dissipated[0], 4);
  EXPECT_TRUE(EnergyRecorder(1.0).due(3)); // at least every step
}

TEST(DivergenceCheck, SpeedLimitIsAThousandTimesTheLoadVelocity) {
  SimulationParams p;
  DivergenceCheck check(p, {0.0, 1.0, 2.0, 3.0});
  const double load = std::abs(p.loading.normal_stress) + std::abs(p.loading.shear_stress);
  EXPECT_DOUBLE_EQ(check.speed_limit(),
                   1000.0 * load / (p.material.density * p.material.s_wave_speed()));
  InterfaceFields f = resting_interface(4, 1.0, std::abs(p.loading.normal_stress), p.friction.mu);
  f.velocity[2] = -0.5 * check.speed_limit();
  check.check(f);
  EXPECT_FALSE(check.diverged());
  EXPECT_EQ(check.max_slip_velocity(), 0.5 * check.speed_limit());
  f.velocity[1] = 2.0 * check.speed_limit();
  check.check(f);
  EXPECT_TRUE(check.diverged());
  char expected[200];
  std::snprintf(expected, sizeof expected,
                "diverged at t = 0.125 s (step 7): slip speed above %.3g m/s or a non-finite field",
                check.speed_limit());
  EXPECT_EQ(check.message(0.125, 7), expected);
}

TEST(DivergenceCheck, NaNAndNonFiniteEnergyDiverge) {
  SimulationParams p;
  InterfaceFields f = resting_interface(3, 1.0, std::abs(p.loading.normal_stress), p.friction.mu);
  DivergenceCheck a(p, f.x1);
  f.velocity[0] = std::numeric_limits<double>::quiet_NaN();
  a.check(f);
  EXPECT_TRUE(a.diverged());
  DivergenceCheck b(p, f.x1);
  b.check_energy({1.0, 2.0, 0.0, 0.0});
  EXPECT_FALSE(b.diverged());
  b.check_energy({std::numeric_limits<double>::infinity(), 2.0, 0.0, 0.0});
  EXPECT_TRUE(b.diverged());
}

TEST(DivergenceCheck, NegativeEnergyInTheSolidIsAnInstability) {
  // EnergyBalance {kinetic, strain, external_work, dissipated}.
  SimulationParams p;
  DivergenceCheck ok(p, {0.0});
  ok.check_energy({0.0, -1e-20, 1e-4, 0.5e-4}); // round-off below zero is not a divergence
  EXPECT_FALSE(ok.diverged());
  DivergenceCheck bad(p, {0.0});
  bad.check_energy({0.0, -1e-8, 1e-4, 0.5e-4});
  EXPECT_TRUE(bad.diverged());
  EXPECT_NE(bad.message(1.0, 10).find("energy in the solid became negative"), std::string::npos)
      << bad.message(1.0, 10);
}

TEST(DivergenceCheck, EachOfTwoSolidsMustHoldANonNegativeEnergy) {
  // EnergyBalance {kinetic, strain, external_work, dissipated, lower_solid}: the lower solid
  // returned energy that the upper one holds; their sum is positive.
  SimulationParams p;
  p.lower.side = LowerSide::elastic;
  DivergenceCheck ok(p, {0.0});
  ok.check_energy({0.0, 5e-5, 1e-4, 0.5e-4, 2e-5});
  EXPECT_FALSE(ok.diverged());
  DivergenceCheck lower(p, {0.0});
  lower.check_energy({0.0, 5e-5, 1e-4, 0.5e-4, -1e-8});
  EXPECT_TRUE(lower.diverged());
  EXPECT_NE(lower.message(1.0, 10).find("energy in the lower solid became negative"),
            std::string::npos)
      << lower.message(1.0, 10);
  DivergenceCheck upper(p, {0.0});
  upper.check_energy({0.0, 5e-5, 1e-4, 0.5e-4, 5e-5 + 1e-8});
  EXPECT_TRUE(upper.diverged());
  EXPECT_NE(upper.message(1.0, 10).find("energy in the upper solid became negative"),
            std::string::npos)
      << upper.message(1.0, 10);
}

TEST(DivergenceCheck, StrengthAboveTheLargestMuPIsUnstable) {
  SimulationParams p;
  const double p0 = std::abs(p.loading.normal_stress);
  InterfaceFields f = resting_interface(3, 0.5, p0, p.friction.mu);
  DivergenceCheck check(p, f.x1);
  f.pressure[1] = 2 * p0; // raises the range to 2 mu p0
  f.strength[1] = 1.5 * p.friction.mu * p0;
  check.check(f);
  EXPECT_FALSE(check.diverged());
  f.strength[2] = 3 * p.friction.mu * p0;
  check.check(f);
  ASSERT_TRUE(check.diverged());
  char expected[400];
  std::snprintf(expected, sizeof expected,
                "diverged at t = 1 s (step 3): frictional strength %.4g Pa at x1 = %.4g m left its "
                "physical range [0, %.4g] Pa: the strength update is unstable",
                3 * p.friction.mu * p0, 1.0, 2 * p.friction.mu * p0);
  EXPECT_EQ(check.message(1.0, 3), expected);
}

TEST(InterfaceSampler, WritesEveryStrideNodeEverySampleInterval) {
  verification::RecordingSink sink;
  OutputSampling out;
  out.interval = 0.3;
  out.space_stride = 2;
  InterfaceFields f = resting_interface(5, 1.0);
  InterfaceSampler sampler(&sink, out, 0.1, 10, f.x1);
  EXPECT_EQ(sampler.every(), 3);
  EXPECT_EQ(sink.layout.x1, (std::vector<double>{0.0, 2.0, 4.0}));
  EXPECT_EQ(sink.layout.expected_samples, 4); // steps 0, 3, 6, 9
  EXPECT_DOUBLE_EQ(sink.layout.sample_interval, 0.3);
  for (long n = 0; n < 10; ++n) {
    f.velocity[2] = double(n);
    sampler.record(f, n, n * 0.1);
  }
  ASSERT_EQ(sink.samples.size(), 4u);
  EXPECT_EQ(sink.samples[1].slip_velocity, (std::vector<double>{0.0, 3.0, 0.0}));
  EXPECT_DOUBLE_EQ(sink.samples[3].time, 0.9);
  InterfaceSampler no_sink(nullptr, out, 0.1, 10, f.x1); // nothing to write to
  no_sink.record(f, 0, 0.0);
}

TEST(ArrestRule, QuietWindowAfterNucleationAndLastArrival) {
  SimulationParams p;
  p.time.arrest_window = 1.0;
  p.time.stop_on_arrest = true;
  const double end = nucleation_end_time(p.nucleation);
  ArrestRule rule(p);
  const double never = -std::numeric_limits<double>::infinity();
  EXPECT_FALSE(rule.update(end + 0.5, never));
  EXPECT_TRUE(rule.update(end + 1.5, never));
  EXPECT_FALSE(rule.update(end + 3.0, end + 2.5)); // a new arrival restarts the window
  EXPECT_FALSE(rule.arrested());
  p.time.stop_on_arrest = false;
  p.nucleation.enabled = false;
  ArrestRule keep_going(p);
  EXPECT_FALSE(keep_going.update(1.0, never)); // arrested, but the run goes on
  EXPECT_TRUE(keep_going.arrested());
}

// An overstressed patch nucleates as long as it takes: the window starts only once the front
// has reached a node outside the patch (FrontTracker::first_arrival_outside).
TEST(ArrestRule, AnOverstressedPatchIsWatchedOnceTheFrontLeavesIt) {
  SimulationParams p;
  p.nucleation.type = NucleationType::overstressed_patch;
  p.time.arrest_window = 1.0;
  ArrestRule rule(p);
  const double inside_only = 0.1, not_yet = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(rule.update(5.0, inside_only, not_yet)); // still nucleating after 4.9 s
  EXPECT_FALSE(rule.arrested());
  EXPECT_FALSE(rule.update(5.5, 5.2, 5.2)); // left the patch at 5.2 s
  EXPECT_TRUE(rule.update(6.3, 5.2, 5.2));

  FrontTracker front(4, 1e-3, {false, true, true, false}); // nodes 1, 2: the patch
  EXPECT_EQ(front.first_arrival_outside(), not_yet);
  front.update({0.0, 1.0, 1.0, 0.0}, 0.05, 0.1);
  EXPECT_EQ(front.first_arrival_outside(), not_yet);
  EXPECT_LT(front.last_new_arrival(), 0.1);
  front.update({0.0, 1.0, 1.0, 1.0}, 0.15, 0.1);
  EXPECT_NEAR(front.first_arrival_outside(), 0.05 + 1e-3 * 0.1, 1e-12); // the crossing
}

TEST(ProgressReporter, ThrottledAfterStepsAndAlwaysAtTheEnd) {
  std::vector<Progress> seen;
  RunHooks hooks;
  hooks.on_progress = [&](const Progress& p) { seen.push_back(p); };
  hooks.progress_interval_s = 3600.0;
  ProgressReporter progress(hooks, 1.0, 0.1, 10, ProgressReporter::Clock::now());
  progress.after_step(0); // the first step always reports
  progress.after_step(1); // within the interval: no report
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_EQ(seen[0].step, 1);
  EXPECT_DOUBLE_EQ(seen[0].time, 0.1);
  EXPECT_DOUBLE_EQ(seen[0].fraction, 0.1);
  progress.final_report(4, 0.4, 2.0);
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_EQ(seen[1].step, 4);
  EXPECT_EQ(seen[1].total_steps, 10);
  EXPECT_DOUBLE_EQ(seen[1].wall_s, 2.0);
  EXPECT_DOUBLE_EQ(seen[1].steps_per_s, 2.0);
  EXPECT_EQ(seen[1].eta_s, 0.0);
  ProgressReporter silent(RunHooks{}, 1.0, 0.1, 10, ProgressReporter::Clock::now());
  silent.after_step(0);
  silent.final_report(1, 0.1, 1.0);
}

// After the first report, steps/s and the ETA come from the steps since the last report, not
// from the mean since the start (which a run whose steps grow dearer would over-estimate).
TEST(ProgressReporter, RateAndEtaFromTheStepsSinceTheLastReport) {
  std::vector<Progress> seen;
  RunHooks hooks;
  hooks.on_progress = [&](const Progress& p) { seen.push_back(p); };
  hooks.progress_interval_s = 0.25;
  // The run started 1000 s ago: its mean rate stays far below one step per second.
  const auto started = ProgressReporter::Clock::now() - std::chrono::seconds(1000);
  ProgressReporter progress(hooks, 1.0, 1e-6, 1000000, started);
  progress.after_step(0);
  ASSERT_EQ(seen.size(), 1u);
  EXPECT_LT(seen[0].steps_per_s, 0.01); // the first report: the mean, 1 step in 1000 s
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  progress.after_step(99999); // 99999 steps in the last ~0.3 s
  ASSERT_EQ(seen.size(), 2u);
  EXPECT_GT(seen[1].steps_per_s, 1000.0); // the mean would be about 100 steps/s
  EXPECT_NEAR(seen[1].eta_s, (1000000 - 100000) / seen[1].steps_per_s, 1e-6 * seen[1].eta_s);
}

} // namespace
} // namespace slipfront
