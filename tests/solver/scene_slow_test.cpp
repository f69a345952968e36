// Case 8, slow part (label `slow`): the paper's scene at the paper's mesh, n_d = 40, with
// tighter checks against the published values (paper Sec. 2-3;
// docs/physics.md "The paper's published values"), and the mesh convergence n_d = 20 -> 40
// by the paper's criterion.
#include "scene_support.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace slipfront {
namespace {

using verification::measure;

// L = 5e-5 m, n_d = 40: paper Fig. 2 and Sec. 2.
TEST(PaperSceneSlow, Nd40ReproducesFigure2) {
  SimulationParams p = verification::paper_scene(40.0, 5e-5);
  p.probes.arrival_x1 = 11.0; // the paper's convergence probe
  const RunResult r = run_simulation(p);
  const Metrics& m = r.metrics;
  const verification::SceneSummary s = verification::summarise(p, r);
  const double t6 = verification::arrival_at(r, 6.0);
  const double cs = p.material.s_wave_speed(), cp = p.material.p_wave_speed();
  EXPECT_EQ(m.outcome, Outcome::arrested);
  // "the rupture stops at x1 ~ 12.5 m": read off the text; +-0.2 m (8 elements).
  EXPECT_NEAR(m.arrest_position, 12.5, 0.2);
  // "maximal slip velocity 8 mm/s in the beginning": +-1 mm/s.
  EXPECT_NEAR(m.max_slip_velocity, 8e-3, 1e-3);
  // "at x1 = 6 m a maximal slip velocity of around 3 mm/s", "reach the point at around
  // 4.5 s" (Sec. 3, for L = 1e-4 and 5e-5 m): +-0.5 mm/s, +-0.1 s.
  EXPECT_NEAR(s.peak_v_at_probe, 3e-3, 0.5e-3);
  EXPECT_NEAR(t6, 4.5, 0.1);
  // "super-shear, c_s < V_r < c_p, during almost its entire propagation", decelerating.
  EXPECT_GT(m.max_rupture_speed, cs);
  EXPECT_LT(m.max_rupture_speed, cp);
  EXPECT_GE(s.supershear_fraction, 0.95);
  EXPECT_GT(s.vr_start, s.vr_end + 0.15);
  EXPECT_LT(m.energy_error, 1e-10);
  measure("paper scene L=5e-5 n_d=40: arrest %.4f m (paper ~12.5), max |V| %.4g m/s (paper ~8e-3), "
          "peak |V| at 6 m %.4g m/s at %.3f s (paper ~3e-3), arrival at 6 m %.4f s (paper ~4.5), "
          "arrival at 11 m %.4f s, max V_r %.4f, V_r %.3f -> %.3f, super-shear fraction %.3f, "
          "energy error %.2e, %ld steps, wall %.1f s",
          m.arrest_position, m.max_slip_velocity, s.peak_v_at_probe, s.peak_time_at_probe, t6,
          m.arrival_time_at_probe, m.max_rupture_speed, s.vr_start, s.vr_end, s.supershear_fraction,
          m.energy_error, m.steps, m.wall_time_s);

  // Mesh convergence n_d = 20 -> 40 (paper Sec. 3: "n_d = 20 suffices for L >= 5e-5 m",
  // judged on the propagation distance, change < 0.5 %). The arrival time at x1 = 11 m is
  // reported: the paper's 0.1 % on it is stated for its L = 5e-6 m case (Fig. 3).
  SimulationParams p20 = p;
  p20.geometry.nodes_per_meter = 20.0;
  const RunResult r20 = run_simulation(p20);
  const double d_prop = std::abs(r20.metrics.propagation_distance / m.propagation_distance - 1);
  const double d_arr = std::abs(r20.metrics.arrival_time_at_probe / m.arrival_time_at_probe - 1);
  EXPECT_LT(d_prop, 0.005);
  measure("mesh convergence L=5e-5 n_d=20 -> 40: propagation %.4f -> %.4f m (change %.3f %%), "
          "arrival at 11 m %.4f -> %.4f s (change %.3f %%)",
          r20.metrics.propagation_distance, m.propagation_distance, 100 * d_prop,
          r20.metrics.arrival_time_at_probe, m.arrival_time_at_probe, 100 * d_arr);
}

// L = 1e-4 m, n_d = 40 (paper Sec. 3, Fig. 4): also ~3 mm/s at x1 = 6 m, reached at ~4.5 s;
// V_r decelerates from about 1.6 to 1.0 m/s, then arrests abruptly.
TEST(PaperSceneSlow, Nd40L1em4MatchesSection3) {
  const SimulationParams p = verification::paper_scene(40.0, 1e-4);
  const RunResult r = run_simulation(p);
  const Metrics& m = r.metrics;
  const verification::SceneSummary s = verification::summarise(p, r);
  EXPECT_EQ(m.outcome, Outcome::arrested);
  EXPECT_NEAR(s.peak_v_at_probe, 3e-3, 0.5e-3);
  EXPECT_NEAR(m.arrival_time_at_probe, 4.5, 0.1);
  EXPECT_GT(m.max_rupture_speed, 1.3);
  EXPECT_LT(m.max_rupture_speed, 1.8);
  EXPECT_NEAR(s.vr_end, 1.0, 0.15);
  EXPECT_LT(m.energy_error, 1e-10);
  measure("paper scene L=1e-4 n_d=40: arrest %.4f m, peak |V| at 6 m %.4g m/s at %.3f s (paper "
          "~3e-3), arrival at 6 m %.4f s (paper ~4.5), max V_r %.4f (paper ~1.6), V_r at 9-10 m "
          "%.3f (paper ~1.0), energy error %.2e, wall %.1f s",
          m.arrest_position, s.peak_v_at_probe, s.peak_time_at_probe, m.arrival_time_at_probe,
          m.max_rupture_speed, s.vr_end, m.energy_error, m.wall_time_s);
}

} // namespace
} // namespace slipfront
