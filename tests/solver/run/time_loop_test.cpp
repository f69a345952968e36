// The time loop on a scripted RuptureMethod (no FE): how it stops (arrest, divergence,
// cancel, end of the duration), what it records, and the method's end warnings.
#include "verification_support.hpp"

#include "solver/run/time_loop.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace slipfront {
namespace {

// A front that reaches node i at step i from node 0 up to node `last`, then stops; node
// `nan_node` gets V = NaN at step `nan_step` (if >= 0).
class ScriptedMethod : public RuptureMethod {
public:
  ScriptedMethod(int nx, double dx, int last, long nan_step = -1)
      : dx_(dx), last_(last), nan_step_(nan_step) {
    f_.x1.resize(nx);
    for (int i = 0; i < nx; ++i)
      f_.x1[i] = i * dx;
    for (auto* v : {&f_.velocity, &f_.half_velocity, &f_.slip, &f_.opening, &f_.shear_traction})
      v->assign(nx, 0.0);
    f_.pressure.assign(nx, 0.0);
    f_.strength.assign(nx, 0.0);
    f_.state.assign(nx, std::int8_t(NodeState::stick));
  }
  void step(bool compute_energy) override {
    if (step_ <= last_) f_.velocity[step_] = f_.half_velocity[step_] = 1.0;
    if (step_ == nan_step_) f_.velocity[0] = std::numeric_limits<double>::quiet_NaN();
    if (compute_energy) ++energy_.kinetic;
    ++step_;
  }
  double dt() const override { return 0.1; }
  const InterfaceFields& interface() const override { return f_; }
  const EnergyBalance& energy() const override { return energy_; }
  MeshInfo mesh_info() const override { return {int(f_.x1.size()), 1, dx_, 1.0, 0.2, 0.1, 1}; }
  std::vector<std::string> end_warnings(double t) const override {
    return {"ended at " + std::to_string(t)};
  }

private:
  InterfaceFields f_;
  EnergyBalance energy_;
  double dx_;
  int last_;
  long nan_step_;
  long step_ = 0;
};

SimulationParams scripted_params() {
  SimulationParams p;
  p.geometry.x_min = 0.0;
  p.geometry.width = 10.0;
  p.nucleation.enabled = false;
  p.time.duration = 5.0; // 50 steps
  p.time.arrest_window = 1.0;
  p.time.stop_on_arrest = true;
  p.output.interval = 0.5;
  p.probes.arrival_x1 = 0.3;
  p.probes.spectrum_x1 = 0.3;
  return p;
}

TEST(TimeLoop, StopsOnArrestAfterTheQuietWindow) {
  ScriptedMethod method(10, 1.0, 3); // the front reaches nodes 0..3 at steps 0..3
  verification::RecordingSink sink;
  RunHooks hooks;
  hooks.sink = &sink;
  const RunResult r = run_time_loop(method, scripted_params(), hooks);
  // Node i crosses just after t_{i-1/2}; node 3 is the last (t = 0.25 s); quiet for 1 s
  // after step 13.
  EXPECT_EQ(r.metrics.outcome, Outcome::arrested);
  EXPECT_EQ(r.metrics.steps, 14);
  EXPECT_EQ(r.probes.time.size(), 14u);
  EXPECT_EQ(r.energy.time.size(), 14u); // dt = 0.1: energy every step
  EXPECT_EQ(sink.samples.size(), 3u);   // steps 0, 5, 10
  EXPECT_EQ(r.metrics.max_slip_velocity, 1.0);
  EXPECT_NEAR(r.front.arrival_time[2], 0.15, 1e-6);
  ASSERT_FALSE(r.metrics.warnings.empty());
  EXPECT_EQ(r.metrics.warnings.back(), "ended at 1.400000");
  EXPECT_FALSE(r.cancelled);
}

TEST(TimeLoop, RunsToTheEndWithoutStopOnArrest) {
  ScriptedMethod method(10, 1.0, 3);
  SimulationParams p = scripted_params();
  p.time.stop_on_arrest = false;
  const RunResult r = run_time_loop(method, p, {});
  EXPECT_EQ(r.metrics.outcome, Outcome::arrested);
  EXPECT_EQ(r.metrics.steps, 50);
}

TEST(TimeLoop, StopsOnDivergenceWithTheStep) {
  ScriptedMethod method(10, 1.0, 3, 6);
  const RunResult r = run_time_loop(method, scripted_params(), {});
  EXPECT_EQ(r.metrics.outcome, Outcome::diverged);
  EXPECT_EQ(r.metrics.steps, 7);
  EXPECT_EQ(r.metrics.message.rfind("diverged at t = 0.6 s (step 6): slip speed above", 0), 0u)
      << r.metrics.message;
}

TEST(TimeLoop, CancelBeforeTheFirstStep) {
  ScriptedMethod method(10, 1.0, 3);
  std::atomic<bool> cancel{true};
  RunHooks hooks;
  hooks.cancel = &cancel;
  int reports = 0;
  hooks.on_progress = [&](const Progress&) { ++reports; };
  const RunResult r = run_time_loop(method, scripted_params(), hooks);
  EXPECT_TRUE(r.cancelled);
  EXPECT_EQ(r.metrics.steps, 0);
  EXPECT_EQ(r.metrics.message, "cancelled at t = 0.000000 s");
  EXPECT_EQ(reports, 1); // the final report
}

} // namespace
} // namespace slipfront
