// The FE method with two elastic blocks (docs/physics.md "Two solids"): the lower block in the
// level pipeline changes no bit under temporal blocking (1-3 threads) or quiet skipping;
// identical materials keep the normal traction at its initial value (mode II symmetry); a
// stiff, heavy lower solid approaches the rigid plane; a bimaterial run is stable, balances
// its energy and dissipates; the step is the smaller of the two blocks' stable steps; plain
// Coulomb friction between different solids is flagged ill-posed.
#include "bit_compare.hpp"
#include "scene_support.hpp"

#include "solver/fe/finite_element_method.hpp"
#include "solver/fe/mesh_stepper.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace slipfront::fe {
namespace {

using namespace bits;

// The paper's scene at n_d = 10 on a second elastic solid.
SimulationParams two_solid_scene(const Material& lower, double lower_height, TopBoundary bottom,
                                 int threads = 2) {
  SimulationParams p = verification::paper_scene(10.0, 5e-5, threads);
  p.lower.side = LowerSide::elastic;
  p.lower.material = lower;
  p.lower.height = lower_height;
  p.lower.bottom = bottom;
  return p;
}

// A stiffer, denser lower solid (c_p 1.15 times the upper's, impedance 1.4 times).
Material bimaterial_lower() {
  Material m;
  m.density = 1.2;
  m.young_modulus = 4.0;
  m.poisson_ratio = 0.3;
  return m;
}

long differing_blocks(const MeshStepper& a, const MeshStepper& b) {
  return differing_nodes(a.displacement(), b.displacement()) +
         differing_nodes(a.velocity(), b.velocity()) +
         differing_nodes(a.lower()->displacement(), b.lower()->displacement()) +
         differing_nodes(a.lower()->velocity(), b.lower()->velocity());
}

struct Variant {
  double mesh_damping;
  TopBoundary top, bottom;
  double height, lower_height;
};

// 400 steps stepped singly on one thread and in blocks of `block` steps on `threads`
// threads; every step of every block compared, both blocks' nodes after each block.
void expect_blocks_change_no_bit(const Variant& v, int block, int threads) {
  SimulationParams p = two_solid_scene(bimaterial_lower(), v.lower_height, v.bottom, threads);
  p.fe.mesh_damping = v.mesh_damping;
  p.top = v.top;
  p.geometry.height = v.height;
  MeshStepper single(p), blocked(p);
  ThreadTeam one(1), team(threads);
  const int steps = 400;
  long diffs = 0;
  for (int n = 0; n < steps; n += block) {
    const int count = std::min(block, steps - n);
    std::vector<bool> energy(count);
    for (int k = 0; k < count; ++k)
      energy[k] = (n + k) % 7 == 0;
    blocked.advance(team, energy);
    for (int k = 0; k < count; ++k) {
      single.step(one, energy[k]);
      diffs += differing_interface(single.interface(), blocked.interface_after(k));
      diffs += differing_energy(single.energy(), blocked.energy_after(k));
    }
    ASSERT_EQ(diffs, 0) << "block at step " << n;
    ASSERT_EQ(differing_blocks(single, blocked), 0) << "step " << n;
  }
  EXPECT_EQ(blocked.swept_node_updates(), single.swept_node_updates());
  EXPECT_GT(single.energy().kinetic, 0.0); // the rupture is running
  verification::measure("two blocks, temporal blocking (h %g m / %g m, damping %g): %d steps per "
                        "block on %d threads, 400 steps: differing values = %ld",
                        v.height, v.lower_height, v.mesh_damping, block, threads, diffs);
}

TEST(TwoBlocks, TemporalBlockingChangesNoBit) {
  // The lower block lower than the upper one (its rows end first), and taller.
  const Variant shorter{0.0, TopBoundary::traction, TopBoundary::traction, 20.0, 6.0};
  expect_blocks_change_no_bit(shorter, 5, 1);
  expect_blocks_change_no_bit(shorter, 8, 2);
  expect_blocks_change_no_bit(shorter, 7, 3);
  const Variant taller{0.0, TopBoundary::traction, TopBoundary::traction, 3.0, 8.0};
  expect_blocks_change_no_bit(taller, 8, 2);
}

TEST(TwoBlocks, TemporalBlockingChangesNoBitWithDampingAndAbsorbingBoundaries) {
  const Variant absorbing{0.1, TopBoundary::absorbing, TopBoundary::absorbing, 3.0, 2.0};
  expect_blocks_change_no_bit(absorbing, 8, 2);
  expect_blocks_change_no_bit(absorbing, 3, 3);
}

TEST(TwoBlocks, QuietSkippingChangesNoBit) {
  for (const double damping : {0.0, 0.1}) {
    SimulationParams p = two_solid_scene(bimaterial_lower(), 3.0, TopBoundary::absorbing);
    p.fe.mesh_damping = damping;
    MeshStepper skipping(p), sweeping(p);
    sweeping.set_skip_quiet(false);
    ThreadTeam team(2);
    const int nx = skipping.nx();
    long narrow_lower_rows = 0;
    for (int n = 0; n < 600; ++n) {
      skipping.step(team, n % 7 == 0);
      sweeping.step(team, n % 7 == 0);
      for (int j = 0; j < skipping.lower()->ny(); ++j) {
        const int width = skipping.lower()->active_columns(j).size();
        narrow_lower_rows += width > 0 && width < nx;
      }
      if (n % 50 != 49) continue;
      ASSERT_EQ(differing_blocks(skipping, sweeping), 0) << "step " << n;
      ASSERT_EQ(differing_interface(skipping.interface(), sweeping.interface()), 0) << "step " << n;
      ASSERT_EQ(differing_energy(skipping.energy(), sweeping.energy()), 0) << "step " << n;
    }
    EXPECT_GT(skipping.energy().kinetic, 0.0);
    EXPECT_GT(narrow_lower_rows, 0); // the lower block's quiet columns were left out
    EXPECT_LT(skipping.swept_node_updates(), sweeping.swept_node_updates());
  }
}

// A shear pulse on |x1| < 1 m (ramped over 1 s, nucleation off): the rupture it starts is
// driven by shear only.
SimulationParams shear_driven(SimulationParams p) {
  p.nucleation.enabled = false;
  p.extra_load = [](double x1, double t) {
    InterfaceTraction load;
    if (std::abs(x1) < 1.0) load.t1 = 0.004 * std::min(t, 1.0);
    return load;
  };
  return p;
}

// Steps a scene `steps` steps; returns the largest |p - p0| / p0 over the interface and the
// steps, and the largest slip rate.
struct NormalTractionRecord {
  double largest_change = 0, largest_slip_rate = 0;
};
NormalTractionRecord run_and_watch_pressure(MeshStepper& mesh, double p0, int steps) {
  ThreadTeam team(2);
  NormalTractionRecord rec;
  for (int n = 0; n < steps; ++n) {
    mesh.step(team, false);
    const InterfaceFields& f = mesh.interface();
    for (std::size_t i = 0; i < f.pressure.size(); ++i) {
      rec.largest_change = std::max(rec.largest_change, std::abs(f.pressure[i] - p0) / p0);
      rec.largest_slip_rate = std::max(rec.largest_slip_rate, std::abs(f.velocity[i]));
    }
  }
  return rec;
}

// The whole interface slides at once (Coulomb, mu_r |tau2_0| < tau1_0): each solid radiates a
// plane S wave, the sides move at +-(tau1_0 - tau_r) / (rho c_s) of their own, and the slip
// rate is the two dashpots in series, V = (tau1_0 - tau_r) (1/(rho c_s)+ + 1/(rho c_s)-),
// until the first reflection returns (2 h / c_s of the faster solid). The mean over a window
// converges to it; the tolerance is the start-up ringing of the discrete chain, as for one
// block (docs/verification.md case 4).
TEST(TwoSolids, UniformSlipIsTheTwoImpedancesInSeries) {
  const double height = 4.0, nd = 20.0;
  SimulationParams p = verification::small_block(1.0, height, nd);
  p.friction.law = "coulomb";
  p.friction.mu = 0.5;
  p.lower.side = LowerSide::elastic;
  p.lower.material = bimaterial_lower();
  p.lower.height = height;
  const double p0 = std::abs(p.loading.normal_stress), tau_r = p.friction.mu * p0;
  const Material &up = p.material, &lo = p.lower.material;
  const double z_up = up.density * up.s_wave_speed(), z_lo = lo.density * lo.s_wave_speed();
  const double V = (p.loading.shear_stress - tau_r) * (1 / z_up + 1 / z_lo);
  const double t_return = 2 * height / std::max(up.s_wave_speed(), lo.s_wave_speed());
  MeshStepper mesh(p);
  ThreadTeam team(1);
  const double t0 = 1.0, t1 = t_return - 0.5;
  double slip0 = NAN, time0 = NAN, pressure_err = 0, spread = 0;
  while (mesh.time() + mesh.dt() <= t1) {
    mesh.step(team, false);
    const InterfaceFields& f = mesh.interface();
    const auto [lo_v, hi_v] = std::minmax_element(f.velocity.begin(), f.velocity.end());
    spread = std::max(spread, *hi_v - *lo_v);
    for (double pressure : f.pressure)
      pressure_err = std::max(pressure_err, std::abs(pressure - p0) / p0);
    if (std::isnan(slip0) && mesh.time() >= t0) {
      slip0 = f.slip[0];
      time0 = mesh.time();
    }
  }
  const double mean_v = (mesh.interface().slip[0] - slip0) / (mesh.time() - time0);
  const double err = std::abs(mean_v / V - 1);
  EXPECT_EQ(spread, 0.0) << "a uniform load gives a uniform motion";
  EXPECT_LT(pressure_err, 1e-12); // no normal coupling in a uniform motion
  EXPECT_LT(err, 2e-3);
  // The rigid plane's velocity, (tau1_0 - tau_r) / (rho c_s)+, is far from it.
  EXPECT_GT(std::abs(mean_v * z_up / (p.loading.shear_stress - tau_r) - 1), 0.5);
  verification::measure("two solids, uniform slip (n_d = %g, h = %g): V expected %.6g m/s, "
                        "mean over [%.2f, %.2f] s = %.6g, rel. error %.3e, pressure err %.1e",
                        nd, height, V, time0, mesh.time(), mean_v, err, pressure_err);
}

TEST(TwoSolids, IdenticalMaterialsKeepTheNormalTractionAtItsInitialValue) {
  // Mode II between identical blocks: u1 is odd and u2 even in x2, so the two sides' normal
  // motions are equal and the gap and the normal traction do not change. The mirrored lower
  // block holds the negated state of the upper one (docs/physics.md "Two solids").
  const SimulationParams base = verification::paper_scene(10.0, 5e-5);
  const SimulationParams p =
      shear_driven(two_solid_scene(base.material, base.geometry.height, TopBoundary::traction));
  const double p0 = std::abs(p.loading.normal_stress);
  MeshStepper mesh(p);
  const NormalTractionRecord rec = run_and_watch_pressure(mesh, p0, 500);
  EXPECT_GT(rec.largest_slip_rate, 1e-3); // the interface slips
  EXPECT_LE(rec.largest_change, 1e-13);
  // The mirrored lower block holds the negated state of the upper one (to round-off: the
  // law's relative normal velocity is computed, not set).
  const ElasticBlock& up = mesh.upper();
  const ElasticBlock& lo = *mesh.lower();
  double asymmetry = 0, largest = 0;
  for (int j = 0; j < up.ny(); ++j)
    for (int i = 0; i < up.nx(); ++i) {
      const double ux = up.displacement().x.at(i, j), uy = up.displacement().y.at(i, j);
      asymmetry = std::max({asymmetry, std::abs(ux + lo.displacement().x.at(i, j)),
                            std::abs(uy + lo.displacement().y.at(i, j))});
      largest = std::max({largest, std::abs(ux), std::abs(uy)});
    }
  EXPECT_LE(asymmetry, 1e-12 * largest);
  verification::measure("identical solids: max |u + u'_lower| = %.3g of max |u| = %.3g", asymmetry,
                        largest);
  verification::measure("identical solids, 500 steps: max |p - p0| / p0 = %.3g, max |V| = %.3g",
                        rec.largest_change, rec.largest_slip_rate);

  // The test can fail: between different solids the slip moves the normal traction.
  MeshStepper bimaterial(
      shear_driven(two_solid_scene(bimaterial_lower(), 20.0, TopBoundary::traction)));
  const NormalTractionRecord other = run_and_watch_pressure(bimaterial, p0, 500);
  EXPECT_GT(other.largest_change, 1e-3);
  verification::measure("bimaterial, 500 steps: max |p - p0| / p0 = %.3g", other.largest_change);
}

// max |slip - slip_rigid| / max |slip_rigid| after `steps` steps of the paper's scene.
double slip_difference_to_rigid(const SimulationParams& p, int steps) {
  SimulationParams rigid = p;
  rigid.lower = LowerSolid{};
  MeshStepper a(p), b(rigid);
  ThreadTeam team(2);
  for (int n = 0; n < steps; ++n) {
    a.step(team, false);
    b.step(team, false);
  }
  double diff = 0, scale = 0;
  for (std::size_t i = 0; i < a.interface().slip.size(); ++i) {
    diff = std::max(diff, std::abs(a.interface().slip[i] - b.interface().slip[i]));
    scale = std::max(scale, std::abs(b.interface().slip[i]));
  }
  EXPECT_GT(scale, 0.0);
  return diff / scale;
}

TEST(TwoSolids, AStiffHeavyLowerSolidApproachesTheRigidPlane) {
  // E and rho both k times the upper solid's: the same wave speeds (and time step), the
  // impedance k times; the lower side's motion, and the difference to the plane, ~ 1/k.
  const SimulationParams base = verification::paper_scene(10.0, 5e-5);
  double previous = 0;
  for (const double k : {1e2, 1e4, 1e6}) {
    Material stiff = base.material;
    stiff.young_modulus *= k;
    stiff.density *= k;
    const double error =
        slip_difference_to_rigid(two_solid_scene(stiff, 6.0, TopBoundary::traction), 300);
    verification::measure("lower solid k = %g: max slip difference to the rigid plane = %.3g", k,
                          error);
    if (previous > 0) {
      EXPECT_LT(error, previous / 30.0) << "k = " << k;
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-4);
}

TEST(TwoSolids, TheStepIsTheSmallerOfTheTwoBlocksStableSteps) {
  Material stiff = bimaterial_lower();
  stiff.young_modulus = 10.0; // c_p about 2.3 times the upper's
  const SimulationParams p = two_solid_scene(stiff, 5.0, TopBoundary::traction);
  const MeshStepper mesh(p);
  ASSERT_LT(mesh.lower()->stable_dt(), mesh.upper().stable_dt());
  EXPECT_EQ(mesh.dt(), p.time.safety_factor * mesh.lower()->stable_dt());
  const SimulationParams same = two_solid_scene(p.material, 5.0, TopBoundary::traction);
  const MeshStepper soft(same);
  EXPECT_EQ(soft.dt(), p.time.safety_factor * soft.upper().stable_dt());
  const TimeStepBounds bounds = FiniteElementMethod::time_step_bounds(p);
  EXPECT_LE(bounds.shortest, mesh.dt());
  // The bound is dx / c_p in closed form, the step from the computed largest eigenvalue of
  // the block (1e-11 relative above it here, nu = 0.3): equal to that accuracy when undamped.
  EXPECT_GE(bounds.longest * (1 + 1e-9), mesh.dt())
      << std::setprecision(17) << bounds.longest << " " << mesh.dt();
  EXPECT_LT(bounds.longest, FiniteElementMethod::time_step_bounds(same).longest);
}

TEST(TwoSolids, ABimaterialRunIsStableBalancesItsEnergyAndDissipates) {
  // The paper's scene (Prakash-Clifton, L = 50 um) on the stiffer, denser lower solid, run
  // through the whole time loop to its end or arrest.
  SimulationParams p = two_solid_scene(bimaterial_lower(), 20.0, TopBoundary::traction);
  const RunResult r = run_simulation(p, {});
  const Metrics& m = r.metrics;
  EXPECT_NE(m.outcome, Outcome::diverged);
  EXPECT_GT(m.propagation_distance, 5.0); // a rupture ran
  // A slip rate of the order of the rigid run's (c_s-scaled), not a blow-up.
  const RunResult rigid = run_simulation(verification::paper_scene(10.0, 5e-5), {});
  EXPECT_LT(m.max_slip_velocity, 3.0 * rigid.metrics.max_slip_velocity);
  // E - E(0) = W - D to round-off (docs/physics.md "Energy balance"), as on the plane.
  EXPECT_LT(m.energy_error, 1e-12);
  // Friction and contact only take energy out: D never decreases.
  const EnergyRecords& e = r.energy;
  ASSERT_GT(e.time.size(), 10u);
  for (std::size_t k = 1; k < e.time.size(); ++k)
    EXPECT_GE(e.dissipated[k], e.dissipated[k - 1]) << "t = " << e.time[k];
  EXPECT_GT(e.dissipated.back(), 0.0);
  verification::measure("bimaterial paper scene (n_d = 10): energy error %.3g, max |V| %.4g "
                        "(rigid %.4g), propagation %.3g m, D = %.4g",
                        m.energy_error, m.max_slip_velocity, rigid.metrics.max_slip_velocity,
                        m.propagation_distance, e.dissipated.back());
}

TEST(TwoSolids, PlainCoulombBetweenDifferentSolidsIsFlaggedIllPosed) {
  SimulationParams p = two_solid_scene(bimaterial_lower(), 2.0, TopBoundary::traction);
  p.geometry.height = 2.0;
  p.friction.law = "coulomb";
  const auto ill_posed = [&] {
    for (const std::string& w : FiniteElementMethod(p).end_warnings(0.0))
      if (w.find("ill-posed") != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(ill_posed());
  p.lower.material = p.material; // identical solids: the homogeneous problem, well-posed
  EXPECT_FALSE(ill_posed());
  p.lower.material = bimaterial_lower();
  p.friction.law = "prakash_clifton";
  EXPECT_FALSE(ill_posed());
  p.lower = LowerSolid{}; // the rigid plane
  p.friction.law = "coulomb";
  EXPECT_FALSE(ill_posed());
}

} // namespace
} // namespace slipfront::fe
