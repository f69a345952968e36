// Case 3: free vibration of the block, conservation of the leapfrog energy; and the fused
// step of MeshStepper against a textbook leapfrog step built from apply_stiffness.
//
// Leapfrog M (v^{n+1/2} - v^{n-1/2}) = -dt K u^n, u^{n+1} = u^n + dt v^{n+1/2} conserves
// exactly (up to round-off) the shadow energy
//   H^{n+1/2} = 1/2 v^{n+1/2}.M v^{n+1/2} + 1/2 u^n.K u^{n+1}
// for a symmetric K: H^{n+1/2} - H^{n-1/2} = 1/2 (v^+ - v^-).M (v^+ + v^-)
// + 1/2 u^n.K (u^{n+1} - u^{n-1}) = -dt/2 K u^n.(v^+ + v^-) + dt/2 u^n.K (v^+ + v^-) = 0.
// The interface is held (Coulomb, mu = 1000, |tau2_0| = 1 Pa, no shear load): the plane
// does no work on a node that does not move, so H is the conserved quantity of the run.
#include "verification_support.hpp"

#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/mesh_stepper.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace slipfront::fe {
namespace {

using verification::measure;

SimulationParams held_block(double width, double height, double nd) {
  SimulationParams p = verification::small_block(width, height, nd);
  p.loading.normal_stress = -1.0;
  p.loading.shear_stress = 0.0;
  p.friction.law = "coulomb";
  p.friction.mu = 1000.0;
  return p;
}

// A smooth 2D field vanishing on the interface row.
void set_smooth_field(MeshStepper& mesh, double width) {
  const double pi = std::numbers::pi, h = mesh.height(), dx = mesh.dx();
  for (int j = 0; j < mesh.ny(); ++j)
    for (int i = 0; i < mesh.nx(); ++i) {
      const double x = i * dx, y = j * dx;
      mesh.displacement().x.at(i, j) =
          1e-3 * std::sin(pi * y / (2 * h)) * std::cos(2 * pi * x / width);
      mesh.displacement().y.at(i, j) =
          5e-4 * std::sin(pi * y / h) * std::sin(4 * pi * x / width) + 2e-4 * y / h;
    }
  mesh.displacement().x.refresh_all_ghosts();
  mesh.displacement().y.refresh_all_ghosts();
  mesh.activate_all_rows();
}

TEST(FreeVibration, LeapfrogShadowEnergyIsConservedToRoundOff) {
  const double width = 4.0;
  SimulationParams p = held_block(width, 2.0, 10.0);
  MeshStepper mesh(p);
  ThreadTeam team(2);
  set_smooth_field(mesh, width);

  const long steps = 20000;
  double h0 = 0, max_drift = 0, max_drift_1000 = 0, kinetic_max = 0;
  for (long n = 0; n < steps; ++n) {
    mesh.step(team, true);
    const EnergyBalance& e = mesh.energy();
    const double H = e.kinetic + e.strain;
    if (n == 0) h0 = H;
    const double drift = std::abs(H - h0) / h0;
    max_drift = std::max(max_drift, drift);
    if (n < 1000) max_drift_1000 = max_drift;
    kinetic_max = std::max(kinetic_max, e.kinetic);
    ASSERT_EQ(e.external_work, 0.0);
    ASSERT_EQ(e.dissipated, 0.0);
  }
  // The field really vibrates: kinetic energy reaches a good part of the total.
  EXPECT_GT(kinetic_max, 0.3 * h0);
  // Periods: the slowest mode (S, quarter wave over h = 2 m) has T = 4 h / c_s = 8 s.
  const double periods = steps * mesh.dt() / (4 * mesh.height() / p.material.s_wave_speed());
  EXPECT_LT(max_drift_1000, 1e-12);
  EXPECT_LT(max_drift, 1e-11);
  measure("free vibration: |H - H0|/H0 max = %.3e over 1000 steps, %.3e over %ld steps (%.0f "
          "periods of the slowest mode, dt = %.5g s)",
          max_drift_1000, max_drift, steps, periods, mesh.dt());
}

// Random u and v (fixed seed) at every node above the interface row, which stays at rest on
// the plane.
void set_random_fields(MeshStepper& mesh) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1e-3, 1e-3);
  for (int j = 1; j < mesh.ny(); ++j)
    for (int i = 0; i < mesh.nx(); ++i) {
      mesh.displacement().x.at(i, j) = U(rng);
      mesh.displacement().y.at(i, j) = U(rng);
      mesh.velocity().x.at(i, j) = U(rng);
      mesh.velocity().y.at(i, j) = U(rng);
    }
  mesh.displacement().x.refresh_all_ghosts();
  mesh.displacement().y.refresh_all_ghosts();
  mesh.velocity().x.refresh_all_ghosts();
  mesh.velocity().y.refresh_all_ghosts();
  mesh.activate_all_rows();
}

double dot(const VectorField& a, const VectorField& b, int nx, int ny, const MeshStepper* mass) {
  double s = 0;
  for (int j = 0; j < ny; ++j) {
    const double m = mass ? mass->node_mass(j) : 1.0;
    for (int i = 0; i < nx; ++i)
      s += m * (a.x.at(i, j) * b.x.at(i, j) + a.y.at(i, j) * b.y.at(i, j));
  }
  return s;
}

// One fused, multi-threaded step equals v^{n+1/2} = v^{n-1/2} - dt M^-1 K u^n,
// u^{n+1} = u^n + dt v^{n+1/2} computed independently (apply_stiffness) at every bulk and
// top node, and the energy terms equal their definitions.
TEST(FreeVibration, FusedStepIsTheTextbookLeapfrogStep) {
  SimulationParams p = held_block(3.0, 2.0, 10.0);
  MeshStepper mesh(p);
  ThreadTeam team(2);
  const int nx = mesh.nx(), ny = mesh.ny();
  set_random_fields(mesh);

  const VectorField u0 = mesh.displacement(), v0 = mesh.velocity();
  VectorField Ku(nx, ny);
  apply_stiffness(build_stencils(q4_plane_strain_stiffness(p.material)), u0, Ku);
  mesh.step(team, true);
  const double dt = mesh.dt();
  double err_v = 0, err_u = 0, vscale = 0;
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double m = mesh.node_mass(j);
      const double vx = v0.x.at(i, j) - dt / m * Ku.x.at(i, j);
      const double vy = v0.y.at(i, j) - dt / m * Ku.y.at(i, j);
      vscale = std::max({vscale, std::abs(vx), std::abs(vy)});
      err_v = std::max({err_v, std::abs(mesh.velocity().x.at(i, j) - vx),
                        std::abs(mesh.velocity().y.at(i, j) - vy)});
      err_u = std::max({err_u, std::abs(mesh.displacement().x.at(i, j) - (u0.x.at(i, j) + dt * vx)),
                        std::abs(mesh.displacement().y.at(i, j) - (u0.y.at(i, j) + dt * vy))});
    }
  EXPECT_LT(err_v / vscale, 1e-13);
  EXPECT_LT(err_u / 1e-3, 1e-13);

  // Energy terms: 1/2 v.M v and 1/2 (K u^n).u^{n+1}.
  const double kinetic = 0.5 * dot(mesh.velocity(), mesh.velocity(), nx, ny, &mesh);
  const double strain = 0.5 * dot(Ku, mesh.displacement(), nx, ny, nullptr);
  const double ek = std::abs(mesh.energy().kinetic - kinetic) / kinetic;
  const double es = std::abs(mesh.energy().strain - strain) / std::abs(strain);
  EXPECT_LT(ek, 1e-12);
  EXPECT_LT(es, 1e-12);
  measure("fused step vs textbook leapfrog: rel. error v %.2e, u %.2e, kinetic %.2e, strain %.2e",
          err_v / vscale, err_u / 1e-3, ek, es);
}

// The mesh-scale damping (fe.mesh_damping = zeta): the fused step is
// v^{n+1/2} = v^{n-1/2} - dt M^-1 K (u^n + a v^{n-1/2}), a = zeta dx / c_s, at every bulk and
// top node; and over a free vibration the leapfrog energy H decreases by exactly the
// dissipated energy the stepper books (H + dissipated = H0 to round-off). The booked work of a
// step, dt v_mid.a K v^{n-1/2}, is not sign-definite step by step (it is dt v_mid.a K v_mid
// >= 0 less dt/2 v_mid.a K (v^{n+1/2} - v^{n-1/2})), so H is not checked for monotony.
TEST(FreeVibration, DampedStepIsTheKelvinVoigtStepAndItsWorkIsDissipated) {
  SimulationParams p = held_block(3.0, 2.0, 10.0);
  p.fe.mesh_damping = 0.5;
  MeshStepper mesh(p);
  ThreadTeam team(2);
  const double a = 0.5 * mesh.dx() / p.material.s_wave_speed();
  EXPECT_DOUBLE_EQ(mesh.damping_coefficient(), a);
  const int nx = mesh.nx(), ny = mesh.ny();
  set_random_fields(mesh);

  const VectorField u0 = mesh.displacement(), v0 = mesh.velocity();
  VectorField w0(nx, ny), Kw(nx, ny);
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      w0.x.at(i, j) = u0.x.at(i, j) + a * v0.x.at(i, j);
      w0.y.at(i, j) = u0.y.at(i, j) + a * v0.y.at(i, j);
    }
    w0.x.refresh_ghosts(j);
    w0.y.refresh_ghosts(j);
  }
  apply_stiffness(build_stencils(q4_plane_strain_stiffness(p.material)), w0, Kw);
  mesh.step(team, true);
  const double dt = mesh.dt();
  double err_v = 0, vscale = 0;
  for (int j = 1; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double m = mesh.node_mass(j);
      const double vx = v0.x.at(i, j) - dt / m * Kw.x.at(i, j);
      const double vy = v0.y.at(i, j) - dt / m * Kw.y.at(i, j);
      vscale = std::max({vscale, std::abs(vx), std::abs(vy)});
      err_v = std::max({err_v, std::abs(mesh.velocity().x.at(i, j) - vx),
                        std::abs(mesh.velocity().y.at(i, j) - vy)});
    }
  EXPECT_LT(err_v / vscale, 1e-13);

  // Free vibration of a smooth field with the damping on.
  MeshStepper damped(p);
  set_smooth_field(damped, 3.0);
  double h0 = 0, balance = 0, h_end = 0;
  for (long n = 0; n < 4000; ++n) {
    damped.step(team, true);
    const EnergyBalance& e = damped.energy();
    const double H = e.kinetic + e.strain;
    if (n == 0) h0 = H + e.dissipated;
    h_end = H;
    balance = std::max(balance, std::abs(H + e.dissipated - h0) / h0);
    ASSERT_EQ(e.external_work, 0.0);
  }
  EXPECT_LT(balance, 1e-11);
  EXPECT_LT(h_end, h0) << "the damping takes energy out";
  measure("damped step (zeta = 0.5): rel. error v %.2e; free vibration over 4000 steps: H/H0 "
          "%.3g, |H + dissipated - H0|/H0 max %.2e",
          err_v / vscale, h_end / h0, balance);
}

} // namespace
} // namespace slipfront::fe
