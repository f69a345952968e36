#include "solver/fe/stable_time_step.hpp"

#include "solver/fe/lumped_mass.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace slipfront::fe {

namespace {

double dot(const VectorField& a, const VectorField& b) {
  double s = 0;
  for (int j = 0; j < a.x.ny(); ++j)
    for (int i = 0; i < a.x.nx(); ++i)
      s += a.x.at(i, j) * b.x.at(i, j) + a.y.at(i, j) * b.y.at(i, j);
  return s;
}

} // namespace

EigenEstimate largest_eigenvalue(const MeshStencils& stencils, int nx, int ny, double dx,
                                 double density, int max_iterations, double tolerance) {
  VectorField x(nx, ny), w(nx, ny), Kw(nx, ny);
  std::mt19937_64 rng(12345); // fixed seed: the estimate is reproducible
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      x.x.at(i, j) = uniform(rng);
      x.y.at(i, j) = uniform(rng);
    }
  EigenEstimate est;
  double previous = 0;
  for (int it = 1; it <= max_iterations; ++it) {
    // Normalise x; then Kw = M^-1/2 K M^-1/2 x, computed as K applied to w = M^-1/2 x.
    const double norm = std::sqrt(dot(x, x));
    for (int j = 0; j < ny; ++j) {
      const double inv_sqrt_m = 1.0 / std::sqrt(lumped_node_mass(j, ny, dx, density));
      for (int i = 0; i < nx; ++i) {
        x.x.at(i, j) /= norm;
        x.y.at(i, j) /= norm;
        w.x.at(i, j) = x.x.at(i, j) * inv_sqrt_m;
        w.y.at(i, j) = x.y.at(i, j) * inv_sqrt_m;
      }
      w.x.refresh_ghosts(j);
      w.y.refresh_ghosts(j);
    }
    apply_stiffness(stencils, w, Kw);
    for (int j = 0; j < ny; ++j) {
      const double inv_sqrt_m = 1.0 / std::sqrt(lumped_node_mass(j, ny, dx, density));
      for (int i = 0; i < nx; ++i) {
        Kw.x.at(i, j) *= inv_sqrt_m;
        Kw.y.at(i, j) *= inv_sqrt_m;
      }
    }
    const double rayleigh = dot(x, Kw); // x has unit norm
    est.lambda_max = rayleigh;
    est.iterations = it;
    est.relative_change = std::abs(rayleigh - previous) / rayleigh;
    if (it > 10 && est.relative_change < tolerance) break;
    previous = rayleigh;
    std::swap(x, Kw);
  }
  return est;
}

double stable_time_step(const MeshStencils& stencils, int nx, int ny, double dx, double density) {
  const int patch = 24;
  int px = std::min(nx, patch);
  if (px % 2 == 1 && px < nx) ++px;
  const int py = std::min(ny, patch);
  const EigenEstimate est = largest_eigenvalue(stencils, px, py, dx, density);
  return 2.0 / std::sqrt(est.lambda_max);
}

double damped_stable_time_step(double undamped_dt, double a) {
  if (a == 0.0) return undamped_dt;
  return std::sqrt(a * a + undamped_dt * undamped_dt) - a;
}

} // namespace slipfront::fe
