// Cases 10 and 11: the run is independent of the number of threads (bit for bit), and the
// cancel flag ends a run within one step.
#include "scene_support.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstring>

namespace slipfront {
namespace {

using verification::measure;

// Bitwise equality of two double arrays (NaN == NaN when their bits agree).
long differing(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return -1;
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (std::memcmp(&a[i], &b[i], sizeof(double)) != 0) ++n;
  return n;
}

bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof(double)) == 0;
}

void expect_bit_identical_across_threads(double mesh_damping) {
  std::vector<RunResult> runs;
  std::vector<verification::RecordingSink> sinks(3);
  for (int threads : {1, 2, 3}) {
    SimulationParams p = verification::paper_scene(10.0, 5e-5, threads);
    p.output.interval = 0.1;
    p.fe.mesh_damping = mesh_damping;
    RunHooks hooks;
    hooks.sink = &sinks[runs.size()];
    runs.push_back(run_simulation(p, hooks));
    EXPECT_EQ(runs.back().mesh.threads, threads);
  }
  long worst = 0;
  for (std::size_t k = 1; k < runs.size(); ++k) {
    const RunResult &a = runs[0], &b = runs[k];
    const long diffs[] = {
        differing(a.probes.time, b.probes.time),
        differing(a.probes.slip_velocity_arrival, b.probes.slip_velocity_arrival),
        differing(a.probes.slip_velocity_spectrum, b.probes.slip_velocity_spectrum),
        differing(a.probes.strength_spectrum, b.probes.strength_spectrum),
        differing(a.energy.kinetic, b.energy.kinetic),
        differing(a.energy.strain, b.energy.strain),
        differing(a.energy.external_work, b.energy.external_work),
        differing(a.energy.dissipated, b.energy.dissipated),
        differing(a.front.arrival_time, b.front.arrival_time),
        differing(a.front.rupture_speed, b.front.rupture_speed)};
    for (long d : diffs) {
      EXPECT_EQ(d, 0) << "threads " << k + 1;
      worst = std::max(worst, d < 0 ? 1L << 40 : d);
    }
    ASSERT_EQ(sinks[0].samples.size(), sinks[k].samples.size());
    long sample_diffs = 0;
    for (std::size_t s = 0; s < sinks[0].samples.size(); ++s) {
      const InterfaceSample &x = sinks[0].samples[s], &y = sinks[k].samples[s];
      sample_diffs += differing(x.slip_velocity, y.slip_velocity) + differing(x.slip, y.slip) +
                      differing(x.shear_traction, y.shear_traction) +
                      differing(x.contact_pressure, y.contact_pressure) +
                      differing(x.strength, y.strength) + (x.state != y.state ? 1 : 0);
    }
    EXPECT_EQ(sample_diffs, 0) << "threads " << k + 1;
    const Metrics &ma = a.metrics, &mb = b.metrics;
    EXPECT_TRUE(same_bits(ma.arrest_position, mb.arrest_position));
    EXPECT_TRUE(same_bits(ma.propagation_distance, mb.propagation_distance));
    EXPECT_TRUE(same_bits(ma.arrival_time_at_probe, mb.arrival_time_at_probe));
    EXPECT_TRUE(same_bits(ma.max_rupture_speed, mb.max_rupture_speed));
    EXPECT_TRUE(same_bits(ma.mean_rupture_speed, mb.mean_rupture_speed));
    EXPECT_TRUE(same_bits(ma.max_slip_velocity, mb.max_slip_velocity));
    EXPECT_TRUE(same_bits(ma.energy_error, mb.energy_error));
    EXPECT_TRUE(same_bits(ma.spectral_frequency, mb.spectral_frequency));
    EXPECT_TRUE(same_bits(ma.spectral_critical_length, mb.spectral_critical_length));
    EXPECT_EQ(ma.outcome, mb.outcome);
    EXPECT_EQ(ma.steps, mb.steps);
    worst = std::max(worst, sample_diffs);
  }
  EXPECT_EQ(runs[0].metrics.outcome, Outcome::arrested);
  measure("threads 1 vs 2 vs 3 (paper scene n_d=10, mesh_damping %g, %ld steps, %zu samples): "
          "differing values = %ld",
          mesh_damping, runs[0].metrics.steps, sinks[0].samples.size(), worst);
}

TEST(Threads, OneTwoAndThreeThreadsGiveBitIdenticalRuns) {
  expect_bit_identical_across_threads(0.0);
}

// With the mesh damping, w = u + a v is advanced row by row with u (also when the threads
// carry different steps of a block, solver/fe/level_pipeline.hpp): still bit for bit.
TEST(Threads, OneTwoAndThreeThreadsGiveBitIdenticalRunsWithMeshDamping) {
  expect_bit_identical_across_threads(0.1);
}

TEST(Cancellation, CancelFlagSetFromProgressEndsTheRunWithinOneStep) {
  SimulationParams p = verification::paper_scene(10.0, 5e-5, 2);
  std::atomic<bool> cancel{false};
  long cancel_at = -1, calls_after = 0;
  RunHooks hooks;
  hooks.cancel = &cancel;
  hooks.progress_interval_s = 0.0; // report after every step
  hooks.on_progress = [&](const Progress& pr) {
    if (cancel_at >= 0) ++calls_after;
    if (pr.step == 100 && cancel_at < 0) {
      cancel_at = pr.step;
      cancel = true;
    }
  };
  const RunResult r = run_simulation(p, hooks);
  EXPECT_TRUE(r.cancelled);
  ASSERT_EQ(cancel_at, 100);
  EXPECT_GE(r.metrics.steps, cancel_at);
  EXPECT_LE(r.metrics.steps, cancel_at + 1);
  EXPECT_NE(r.metrics.message.find("cancel"), std::string::npos) << r.metrics.message;
  EXPECT_LE(calls_after, 1) << "only the final report may follow the cancel";
  EXPECT_NEAR(r.metrics.simulated_time, r.metrics.steps * r.metrics.dt, 1e-12);

  // A flag set before the start: no step at all.
  std::atomic<bool> early{true};
  RunHooks h2;
  h2.cancel = &early;
  const RunResult r2 = run_simulation(p, h2);
  EXPECT_TRUE(r2.cancelled);
  EXPECT_EQ(r2.metrics.steps, 0);
  measure("cancellation: flag set at step %ld, run ended after %ld steps (message \"%s\"); "
          "pre-set flag: %ld steps",
          cancel_at, r.metrics.steps, r.metrics.message.c_str(), r2.metrics.steps);
}

} // namespace
} // namespace slipfront
