// A slip-weakening rupture started by an overstressed patch and stopped by a barrier of high
// static friction set by a `profiles` entry, by both methods (docs/verification.md): the
// rupture leaves the patch, runs both ways, and arrests where the barrier begins; nothing
// beyond the barrier slips. Also: the prestressed patch without nucleation is a resting
// equilibrium (enabled = false switches it off).
#include "verification_support.hpp"

#include "solver/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

using verification::measure;

constexpr double barrier = 3.0; // mu_s = 10 for |x1| > 3 m

// The paper's material and load on a 10 m periodic interface, n_d = 20: linear slip
// weakening (mu_s 0.75, mu_d 0.5, D_c 1 mm) with the time-scale regularisation, an
// overstressed patch on [-0.6, 0.6] m and the barrier.
SimulationParams barrier_scene(Method method) {
  SimulationParams p;
  p.method = method;
  p.threads = 2;
  p.geometry.width = 10.0;
  p.geometry.x_min = -5.0;
  p.geometry.height = 5.0;
  p.geometry.nodes_per_meter = 20.0;
  p.top = TopBoundary::absorbing;
  p.friction.law = "slip_weakening";
  p.friction.mu_s = 0.75;
  p.friction.mu_d = 0.5;
  p.friction.D_c = 1e-3;
  p.friction.regularization = "time_scale";
  p.friction.t_star = 0.05;
  p.nucleation.type = NucleationType::overstressed_patch;
  p.nucleation.x1_min = -0.6;
  p.nucleation.x1_max = 0.6;
  p.nucleation.shear_stress = 0.0116; // above mu_s |sigma0| = 0.01125 Pa
  Profile wall;
  wall.x1_min = -barrier;
  wall.x1_max = barrier;
  wall.outside = true;
  wall.friction = {{&FrictionValues::mu_s, 10.0}};
  p.profiles = {wall};
  p.time.duration = 12.0;
  p.probes.arrival_x1 = 2.0;
  p.probes.spectrum_x1 = 2.0;
  return p;
}

TEST(SlipWeakeningScene, OverstressedPatchRuptureArrestsAtTheBarrier) {
  for (Method method : {Method::finite_element, Method::spectral_bi}) {
    const SimulationParams p = barrier_scene(method);
    const RunResult r = run_simulation(p);
    const Metrics& m = r.metrics;
    const double dx = 1.0 / p.geometry.nodes_per_meter;
    const char* name = method == Method::finite_element ? "FE" : "BI";
    EXPECT_EQ(m.outcome, Outcome::arrested) << name << ": " << m.message;
    EXPECT_NEAR(m.arrest_position, barrier, 3 * dx) << name;
    EXPECT_NEAR(m.propagation_distance, 2 * barrier, 6 * dx) << name;
    EXPECT_TRUE(std::isfinite(m.arrival_time_at_probe)) << name;
    double beyond = 0;
    for (std::size_t i = 0; i < r.front.x1.size(); ++i)
      if (std::abs(r.front.x1[i]) > barrier && !std::isnan(r.front.arrival_time[i])) ++beyond;
    EXPECT_EQ(beyond, 0) << name << ": nodes beyond the barrier slipped";
    // The rupture grows from the patch, both ways: the front arrives later the farther a
    // node is from the patch, on either side.
    auto arrival = [&](double x1) {
      const int i = int(std::lround((x1 - p.geometry.x_min) / dx));
      return r.front.arrival_time[i];
    };
    for (double side : {-1.0, 1.0}) {
      EXPECT_LT(arrival(side * 0.5), arrival(side * 1.0)) << name;
      EXPECT_LT(arrival(side * 1.0), arrival(side * 2.0)) << name;
      EXPECT_LT(arrival(side * 2.0), arrival(side * 2.9)) << name;
    }
    measure("slip weakening, overstressed patch, barrier at |x1| = 3 m, %s n_d = 20: outcome %s "
            "at t = %.3g s, arrest position %.4g m, propagation %.4g m, arrival at x1 = 2 m "
            "%.4g s, max V_r %.3g m/s",
            name, to_string(m.outcome), m.simulated_time, m.arrest_position, m.propagation_distance,
            m.arrival_time_at_probe, m.max_rupture_speed);
  }
}

TEST(SlipWeakeningScene, WithoutTheBarrierTheRupturePassesIt) {
  // The same scene without the profile: the rupture runs past |x1| = 3 m (so the barrier
  // is what stopped it above).
  for (Method method : {Method::finite_element, Method::spectral_bi}) {
    SimulationParams p = barrier_scene(method);
    p.profiles.clear();
    p.time.duration = 5.0;
    const RunResult r = run_simulation(p);
    int beyond = 0;
    for (std::size_t i = 0; i < r.front.x1.size(); ++i)
      if (std::abs(r.front.x1[i]) > barrier + 0.5 && !std::isnan(r.front.arrival_time[i])) ++beyond;
    EXPECT_GT(beyond, 20) << (method == Method::finite_element ? "FE" : "BI");
  }
}

TEST(SlipWeakeningScene, WithoutNucleationThePrestressedInterfaceRests) {
  for (Method method : {Method::finite_element, Method::spectral_bi}) {
    SimulationParams p = barrier_scene(method);
    p.nucleation.enabled = false; // no patch either
    p.time.duration = 2.0;
    const RunResult r = run_simulation(p);
    EXPECT_EQ(r.metrics.max_slip_velocity, 0.0);
    EXPECT_EQ(r.metrics.outcome, Outcome::no_rupture);
  }
}

} // namespace
} // namespace slipfront
