// The bulk rows' K u in the symmetric form of the square element (solver/fe/stencil.hpp): the
// interior stencil has that form for any elastic material, the bottom and top stencils do
// not, and the velocity update with it differs from the stencil as assembled only by
// rounding (a few units in the last place of the largest term).
#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/params.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace slipfront::fe {
namespace {

MeshStencils stencils_of(double poisson) {
  Material m;
  m.poisson_ratio = poisson;
  return build_stencils(q4_plane_strain_stiffness(m));
}

TEST(StencilSymmetry, TheInteriorStencilHasTheSymmetricFormTheBoundaryRowsDoNot) {
  for (double nu : {0.0, 0.25, 0.33, 0.45}) {
    const MeshStencils s = stencils_of(nu);
    SymmetricStencil k;
    ASSERT_TRUE(symmetric_form(s.interior, k)) << "nu = " << nu;
    EXPECT_EQ(k.xx0, s.interior.b[1][1].xx);
    EXPECT_EQ(k.xx_c, s.interior.b[2][2].xx);
    EXPECT_EQ(k.d, s.interior.b[0][0].xy);
    EXPECT_NE(k.d, 0.0); // the corners couple x and y
    EXPECT_FALSE(symmetric_form(s.bottom, k)) << "nu = " << nu;
    EXPECT_FALSE(symmetric_form(s.top, k)) << "nu = " << nu;
  }
  // A corner block changed beyond rounding breaks the form.
  MeshStencils s = stencils_of(0.25);
  s.interior.b[2][2].xx *= 1.0 + 1e-9;
  SymmetricStencil k;
  EXPECT_FALSE(symmetric_form(s.interior, k));
}

// v <- v - dt/m K u over one row with random u: the symmetric form against K u summed as
// assembled (for_each_node_force), for the plain and the damped update.
TEST(StencilSymmetry, VelocityUpdateDiffersFromTheAssembledStencilOnlyByRounding) {
  const MeshStencils s = stencils_of(0.25);
  const int nx = 257;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  std::vector<std::vector<double>> u(6, std::vector<double>(nx + 2)), w = u;
  for (auto* field : {&u, &w})
    for (auto& row : *field)
      for (double& x : row)
        x = uniform(rng);
  auto row = [](std::vector<std::vector<double>>& f, int r) { return f[r].data() + 1; };
  // K u as assembled, in the stencil's own order.
  std::vector<double> kx(nx), ky(nx), kwx(nx), kwy(nx);
  for_each_node_force(s.interior, row(u, 0), row(u, 1), row(u, 2), row(u, 3), row(u, 4), row(u, 5),
                      nx, [&](int i, double fx, double fy) {
                        kx[i] = fx;
                        ky[i] = fy;
                      });
  for_each_node_force(s.interior, row(w, 0), row(w, 1), row(w, 2), row(w, 3), row(w, 4), row(w, 5),
                      nx, [&](int i, double fx, double fy) {
                        kwx[i] = fx;
                        kwy[i] = fy;
                      });
  double largest = 0; // the largest coefficient: the scale of one term
  for (const auto& r : s.interior.b)
    for (const Block2& b : r)
      largest = std::max({largest, std::abs(b.xx), std::abs(b.xy), std::abs(b.yy)});
  const double dt = 1e-3, mass = 2.0, scale = dt / mass * largest; // |u| <= 1
  // 18 terms of size <= scale each, summed in another order: a few units in the last
  // place of the largest possible sum (v starts at 0, so v is -dt/m K u itself).
  const double bound = 18 * 4 * std::numeric_limits<double>::epsilon() * scale;

  std::vector<double> vx(nx, 0.0), vy(nx, 0.0), kin(nx), str(nx);
  stencil_velocity_update(s.interior, row(u, 0), row(u, 1), row(u, 2), row(u, 3), row(u, 4),
                          row(u, 5), vx.data(), vy.data(), nx, dt, mass, kin.data(), str.data());
  std::vector<double> dvx(nx, 0.0), dvy(nx, 0.0), dis(nx);
  stencil_damped_velocity_update(s.interior, row(u, 0), row(u, 1), row(u, 2), row(u, 3), row(u, 4),
                                 row(u, 5), row(w, 0), row(w, 1), row(w, 2), row(w, 3), row(w, 4),
                                 row(w, 5), dvx.data(), dvy.data(), nx, dt, mass, dis.data());
  double worst = 0, worst_damped = 0;
  long exact = 0;
  for (int i = 0; i < nx; ++i) {
    const double ex = 0.0 - dt / mass * kx[i], ey = 0.0 - dt / mass * ky[i];
    worst = std::max({worst, std::abs(vx[i] - ex), std::abs(vy[i] - ey)});
    exact += (vx[i] == ex) + (vy[i] == ey);
    const double dx = 0.0 - dt / mass * kwx[i], dy = 0.0 - dt / mass * kwy[i];
    worst_damped = std::max({worst_damped, std::abs(dvx[i] - dx), std::abs(dvy[i] - dy)});
    EXPECT_NEAR(kin[i], vx[i] * vx[i] + vy[i] * vy[i], 1e-15);
  }
  EXPECT_LE(worst, bound);
  EXPECT_LE(worst_damped, bound);
  EXPECT_GT(worst, 0.0) << "the symmetric form was not used: every bit is the assembled one";
  std::printf("[measure] symmetric stencil vs assembled: max |dv| = %.3g (bound %.3g, "
              "%.3g of a term); %ld of %d values bit-equal\n",
              worst, bound, worst / scale, exact, 2 * nx);
}

} // namespace
} // namespace slipfront::fe
