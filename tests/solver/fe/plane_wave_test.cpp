// Case 2: plane P and S waves, phase speed against the exact dispersion relation.
//
// Set-up: a block uniform in x1 (periodic direction trivially satisfied), its interface
// held by a Coulomb contact that cannot slip (mu = 1000, |tau2_0| = 1 Pa, no shear load),
// its top free. A field u(x2) uniform in x1 reduces the Q4/2x2-Gauss/lumped-mass mesh
// exactly to a 1D chain of linear elements with modulus M (= lambda + 2 mu for u2, P
// wave; = mu for u1, S wave) and nodal mass rho dx^2 (half on the free top). Its
// eigenmodes with a fixed bottom and a free top are exactly s_j = sin(k j dx),
// k = (2n - 1) pi / (2 h) (the free end is a mirror: u_{N+1} = u_{N-1}), with
//   omega_h^2 = (4 c^2 / dx^2) sin^2(k dx / 2)            (semi-discrete)
//   cos(Omega dt) = 1 - omega_h^2 dt^2 / 2                (central differences)
// so the numerical phase speed is c_h = Omega / k = c (1 - (k dx)^2 (1 - C^2) / 24 + ...),
// C = c dt / dx: second order in dx at a fixed Courant number.
//
// The test starts the exact discrete standing wave u^n = A s cos(Omega n dt) (u^0 = A s,
// v^{-1/2} = A s (1 - cos(Omega dt)) / dt), runs the solver, and measures Omega from the
// computed modal amplitude a_n through the three-term recurrence
// a_{n+1} + a_{n-1} = 2 cos(Omega dt) a_n (least squares over every step).
#include "verification_support.hpp"

#include "solver/fe/mesh_stepper.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace slipfront::fe {
namespace {

using verification::measure;

struct WaveResult {
  double speed = 0;           // measured phase speed Omega / k
  double discrete_speed = 0;  // exact phase speed of the discrete scheme
  double continuum_speed = 0; // c
  double mode_residual = 0;   // max |u - a s| / A: the field stays in the mode
  double courant = 0;
  double k_dx = 0;
};

// component 0: u1 (S wave), 1: u2 (P wave). Mode n: k = (2n - 1) pi / (2h).
WaveResult standing_wave(int component, double nodes_per_meter, double height, int mode,
                         double duration) {
  SimulationParams p = verification::small_block(1.0, height, nodes_per_meter);
  p.loading.normal_stress = -1.0;
  p.loading.shear_stress = 0.0;
  p.friction.law = "coulomb";
  p.friction.mu = 1000.0;
  MeshStepper mesh(p);
  ThreadTeam team(1);

  const double dx = mesh.dx(), dt = mesh.dt(), h = mesh.height();
  const int nx = mesh.nx(), ny = mesh.ny();
  const double c = component == 0 ? p.material.s_wave_speed() : p.material.p_wave_speed();
  const double k = (2 * mode - 1) * std::numbers::pi / (2 * h);
  const double omega_h = 2 * c / dx * std::sin(k * dx / 2);
  const double cos_Odt = 1 - 0.5 * omega_h * omega_h * dt * dt;
  const double A = 1e-3;

  NodalField& u = component == 0 ? mesh.displacement().x : mesh.displacement().y;
  NodalField& v = component == 0 ? mesh.velocity().x : mesh.velocity().y;
  std::vector<double> s(ny);
  double ss = 0;
  for (int j = 0; j < ny; ++j) {
    s[j] = std::sin(k * j * dx);
    ss += s[j] * s[j];
    for (int i = 0; i < nx; ++i) {
      u.at(i, j) = A * s[j];
      v.at(i, j) = A * s[j] * (1 - cos_Odt) / dt;
    }
  }
  for (int i = 0; i < nx; ++i)
    u.at(i, 0) = v.at(i, 0) = 0.0; // the held interface (s_0 = 0)
  mesh.displacement().x.refresh_all_ghosts();
  mesh.displacement().y.refresh_all_ghosts();
  mesh.activate_all_rows();

  WaveResult r;
  const long steps = long(duration / dt);
  std::vector<double> a;
  a.reserve(steps + 1);
  for (long n = 0; n <= steps; ++n) {
    // Modal amplitude of u^n (column 0; the field is uniform in x1) and the residual.
    double proj = 0;
    for (int j = 0; j < ny; ++j)
      proj += u.at(0, j) * s[j];
    proj /= ss;
    a.push_back(proj);
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; i += std::max(1, nx / 4))
        r.mode_residual = std::max(r.mode_residual, std::abs(u.at(i, j) - proj * s[j]) / A);
    if (n < steps) mesh.step(team, false);
  }
  double num = 0, den = 0;
  for (std::size_t n = 1; n + 1 < a.size(); ++n) {
    num += a[n] * (a[n + 1] + a[n - 1]);
    den += 2 * a[n] * a[n];
  }
  const double cos_measured = num / den;
  r.speed = std::acos(cos_measured) / dt / k;
  r.discrete_speed = std::acos(cos_Odt) / dt / k;
  r.continuum_speed = c;
  r.courant = c * dt / dx;
  r.k_dx = k * dx;
  return r;
}

void convergence(int component, const char* name) {
  const double height = 3.0; // mode 3: wavelength 2.4 m, 12 elements per wavelength at n_d = 5
  const int mode = 3;
  double previous_error = 0;
  std::vector<double> ratios;
  for (double nd : {5.0, 10.0, 20.0, 40.0}) {
    const WaveResult r = standing_wave(component, nd, height, mode, 6.0);
    const double err = std::abs(r.speed / r.continuum_speed - 1);
    const double vs_scheme = std::abs(r.speed / r.discrete_speed - 1);
    // 1. The solver is exactly the scheme: the measured phase speed is the discrete one.
    EXPECT_LT(vs_scheme, 1e-9) << name << " n_d = " << nd;
    EXPECT_LT(r.mode_residual, 1e-9) << name << " n_d = " << nd;
    // 2. The discrete scheme lags (C < 1) by (k dx)^2 (1 - C^2) / 24 to leading order.
    const double leading = r.k_dx * r.k_dx * (1 - r.courant * r.courant) / 24;
    EXPECT_LT(r.speed, r.continuum_speed);
    EXPECT_NEAR(err / leading, 1.0, 0.05) << name << " n_d = " << nd;
    measure("wave %s n_d=%g: c_h = %.10f, c = %.10f, |c_h/c - 1| = %.4e, |c_h/c_scheme - 1| = "
            "%.2e, mode residual = %.2e, C = %.4f, k dx = %.4f",
            name, nd, r.speed, r.continuum_speed, err, vs_scheme, r.mode_residual, r.courant,
            r.k_dx);
    if (previous_error > 0) ratios.push_back(previous_error / err);
    previous_error = err;
  }
  // 3. Second order: the error falls by ~4 per halving of dx.
  for (double q : ratios)
    EXPECT_NEAR(q, 4.0, 0.15) << name;
  measure("wave %s: error ratios per halving of dx = %.4f %.4f %.4f", name, ratios[0], ratios[1],
          ratios[2]);
  EXPECT_LT(previous_error, 2e-3) << name << " at n_d = 40";
}

TEST(PlaneWave, PWaveAlongX2ConvergesAtSecondOrderToCp) {
  convergence(1, "P");
}

TEST(PlaneWave, SWaveAlongX2ConvergesAtSecondOrderToCs) {
  convergence(0, "S");
}

} // namespace
} // namespace slipfront::fe
