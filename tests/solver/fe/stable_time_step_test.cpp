// Case 9: the stable time step.
//
// Central differences are stable for dt <= 2 / omega_max, omega_max^2 the largest
// eigenvalue of M^-1 K. For the free block (periodic in x1, free top and bottom) with
// these Q4 elements and lumped mass, omega_max = 2 c_p / dx exactly: the mode u2 = (-1)^j,
// uniform in x1, is a free-free 1D chain at its cut-off, (K u)_j = 4 (lambda + 2 mu) u_j on
// masses rho dx^2 (rho dx^2 / 2 with half the springs at the ends). So dt_stable = dx / c_p,
// for any Poisson ratio; a dense Cholesky certificate below confirms it is the largest.
//
// Checks: (1) power iteration on the whole small mesh = the certified lambda_max; (2) the patch
// estimate used by the solver (<= 24 x 24 nodes) = the power iteration on the whole mesh
// and = dx / c_p; (3) a run above the limit diverges (and says so), below it does not.
#include "dense_symmetric.hpp"
#include "verification_support.hpp"

#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/stable_time_step.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/simulation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slipfront::fe {
namespace {

using verification::measure;

// Certifies that lambda* = 4 c_p^2 / dx^2 is the largest eigenvalue of M^-1/2 K M^-1/2 on the
// free nx x ny block: (a) the mode u2 = (-1)^j is an eigenvector with eigenvalue lambda*,
// (b) lambda* (1 + eps) I - A is positive definite (Cholesky of the dense matrix), so no
// eigenvalue exceeds lambda* (1 + eps). Returns the eigen-residual of (a), relative.
double certify_largest_eigenvalue(const MeshStencils& st, int nx, int ny, double dx, double rho,
                                  double lambda_star, double eps) {
  const int n = 2 * nx * ny;
  verification::Dense A(n);
  VectorField u(nx, ny), Ku(nx, ny);
  auto mass = [&](int j) { return (j == 0 || j == ny - 1 ? 0.5 : 1.0) * rho * dx * dx; };
  for (int c = 0; c < n; ++c) {
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        u.x.at(i, j) = u.y.at(i, j) = 0.0;
    const int node = c / 2, i = node % nx, j = node / nx;
    (c % 2 ? u.y : u.x).at(i, j) = 1.0 / std::sqrt(mass(j));
    u.x.refresh_all_ghosts();
    u.y.refresh_all_ghosts();
    apply_stiffness(st, u, Ku);
    for (int jj = 0; jj < ny; ++jj)
      for (int ii = 0; ii < nx; ++ii) {
        const int r = 2 * (jj * nx + ii);
        A(r, c) = Ku.x.at(ii, jj) / std::sqrt(mass(jj));
        A(r + 1, c) = Ku.y.at(ii, jj) / std::sqrt(mass(jj));
      }
  }
  double asym = 0, amax = 0;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      asym = std::max(asym, std::abs(A(r, c) - A(c, r)));
      amax = std::max(amax, std::abs(A(r, c)));
    }
  EXPECT_LT(asym / amax, 1e-13) << "M^-1/2 K M^-1/2 must be symmetric";

  // (a) x = M^1/2 (0, (-1)^j): A x = lambda* x.
  std::vector<double> x(n, 0.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      x[2 * (j * nx + i) + 1] = (j % 2 ? -1.0 : 1.0) * std::sqrt(mass(j));
  double residual = 0, xmax = 0;
  for (int r = 0; r < n; ++r) {
    double Ax = 0;
    for (int c = 0; c < n; ++c)
      Ax += A(r, c) * x[c];
    residual = std::max(residual, std::abs(Ax - lambda_star * x[r]));
    xmax = std::max(xmax, std::abs(x[r]));
  }
  // (b) lambda* (1 + eps) I - A > 0, and lambda* (1 - eps) I - A is not (lambda* is attained).
  verification::Dense B(n), C(n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      B(r, c) = (r == c ? lambda_star * (1 + eps) : 0.0) - A(r, c);
      C(r, c) = (r == c ? lambda_star * (1 - eps) : 0.0) - A(r, c);
    }
  EXPECT_TRUE(verification::positive_definite(B)) << "an eigenvalue above lambda*";
  EXPECT_FALSE(verification::positive_definite(C));
  return residual / (lambda_star * xmax);
}

TEST(StableTimeStep, PowerIterationMatchesTheDenseEigenvalueAndTheAnalyticBound) {
  for (double nu : {0.25, 0.0, 0.45}) {
    Material mat;
    mat.poisson_ratio = nu;
    const MeshStencils st = build_stencils(q4_plane_strain_stiffness(mat));
    const double dx = 0.1, rho = mat.density;
    const double analytic = 4 * std::pow(mat.p_wave_speed() / dx, 2);
    for (auto [nx, ny] : {std::pair{8, 6}, std::pair{12, 10}, std::pair{7, 5}}) {
      const double residual = certify_largest_eigenvalue(st, nx, ny, dx, rho, analytic, 1e-10);
      EXPECT_LT(residual, 1e-13);
      const double power = largest_eigenvalue(st, nx, ny, dx, rho).lambda_max;
      EXPECT_NEAR(power / analytic, 1.0, 1e-6) << "nu " << nu << " mesh " << nx << "x" << ny;
      EXPECT_LE(power, analytic * (1 + 1e-12)); // a Rayleigh quotient never exceeds lambda_max
      measure("stable step nu=%g mesh %dx%d: lambda_max = 4 c_p^2/dx^2 certified (eigen-residual "
              "%.1e, Cholesky at 1 +- 1e-10); power iteration / lambda_max - 1 = %.2e",
              nu, nx, ny, residual, power / analytic - 1);
    }
  }
}

TEST(StableTimeStep, PatchEstimateEqualsWholeMeshPowerIteration) {
  const Material mat;
  const MeshStencils st = build_stencils(q4_plane_strain_stiffness(mat));
  const double dx = 0.05, rho = mat.density;
  const double exact_dt = dx / mat.p_wave_speed();
  for (auto [nx, ny] :
       {std::pair{30, 30}, std::pair{40, 24}, std::pair{24, 41}, std::pair{50, 35}}) {
    const double patch_dt = stable_time_step(st, nx, ny, dx, rho);
    const EigenEstimate full = largest_eigenvalue(st, nx, ny, dx, rho);
    const double full_dt = 2 / std::sqrt(full.lambda_max);
    EXPECT_NEAR(patch_dt / full_dt, 1.0, 1e-6) << nx << "x" << ny;
    EXPECT_NEAR(patch_dt / exact_dt, 1.0, 1e-6) << nx << "x" << ny;
    measure("stable step mesh %dx%d: patch dt / full-mesh dt - 1 = %.2e, patch dt / (dx/c_p) - 1 "
            "= %.2e, full dt / (dx/c_p) - 1 = %.2e (%d iterations)",
            nx, ny, patch_dt / full_dt - 1, patch_dt / exact_dt - 1, full_dt / exact_dt - 1,
            full.iterations);
  }
}

// A block whose interface is disturbed (a short shear pulse that makes part of it slip):
// with dt above the stable step round-off in the highest mode grows at every step.
RunResult disturbed_run(double safety_factor, double mesh_damping = 0.0) {
  SimulationParams p = verification::small_block(2.0, 2.0, 10.0);
  p.fe.mesh_damping = mesh_damping;
  p.friction.law = "coulomb";
  p.time.safety_factor = safety_factor;
  p.time.duration = 6.0;
  p.output.interval = 0.05;
  p.extra_load = [](double x1, double t) {
    return InterfaceTraction{t < 0.5 ? 0.002 * std::sin(std::numbers::pi * x1) : 0.0, 0.0};
  };
  return run_simulation(p);
}

TEST(StableTimeStep, RunAboveTheStableStepDivergesBelowItDoesNot) {
  const RunResult above = disturbed_run(1.05);
  EXPECT_EQ(above.metrics.outcome, Outcome::diverged);
  EXPECT_NE(above.metrics.message.find("diverged"), std::string::npos) << above.metrics.message;
  const RunResult below = disturbed_run(0.95);
  EXPECT_NE(below.metrics.outcome, Outcome::diverged) << below.metrics.message;
  EXPECT_GT(below.metrics.max_slip_velocity, 0.0) << "the pulse must make the interface slip";
  EXPECT_LT(below.metrics.max_slip_velocity, 0.1);
  EXPECT_LT(below.metrics.energy_error, 1e-10);
  measure("stable step run: safety 1.05 -> %s after %ld steps (%s); safety 0.95 -> %s, %ld steps, "
          "max V = %.3g m/s, energy error = %.2e",
          to_string(above.metrics.outcome), above.metrics.steps, above.metrics.message.c_str(),
          to_string(below.metrics.outcome), below.metrics.steps, below.metrics.max_slip_velocity,
          below.metrics.energy_error);
}

// With the mesh-scale damping -a K v^{n-1/2} (a = zeta dx / c_s) the stable step is
// sqrt(a^2 + dt0^2) - a (damped_stable_time_step): zeta = 1 takes it to 0.27 dt0 on this
// mesh, and the bound is sharp: 5 % above it the run diverges, 5 % below it does not.
TEST(StableTimeStep, DampedRunAboveTheDampedStableStepDivergesBelowItDoesNot) {
  const double dt0 = 0.1 / Material{}.p_wave_speed(), a = 0.1 / Material{}.s_wave_speed();
  EXPECT_EQ(damped_stable_time_step(dt0, 0.0), dt0);
  EXPECT_NEAR(damped_stable_time_step(dt0, a), std::sqrt(a * a + dt0 * dt0) - a, 1e-15);
  const RunResult above = disturbed_run(1.05, 1.0);
  EXPECT_EQ(above.metrics.outcome, Outcome::diverged);
  const RunResult below = disturbed_run(0.95, 1.0);
  EXPECT_NE(below.metrics.outcome, Outcome::diverged) << below.metrics.message;
  EXPECT_GT(below.metrics.max_slip_velocity, 0.0);
  EXPECT_LT(below.metrics.max_slip_velocity, 0.1);
  EXPECT_LT(below.metrics.energy_error, 1e-10) << "the damping's work is in the dissipated energy";
  EXPECT_NEAR(below.mesh.stable_dt, damped_stable_time_step(dt0, a), 1e-6 * dt0);
  measure("damped stable step (zeta = 1, n_d = 10): stable dt = %.5g s = %.3f of the undamped; "
          "safety 1.05 -> %s after %ld steps; safety 0.95 -> %s, %ld steps, max V = %.3g m/s, "
          "energy error = %.2e",
          below.mesh.stable_dt, below.mesh.stable_dt / dt0, to_string(above.metrics.outcome),
          above.metrics.steps, to_string(below.metrics.outcome), below.metrics.steps,
          below.metrics.max_slip_velocity, below.metrics.energy_error);
}

} // namespace
} // namespace slipfront::fe
