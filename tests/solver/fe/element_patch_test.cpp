// Case 1: patch tests of the Q4 plane-strain element and of the mesh stencil.
//
// A linear displacement field has a constant stress sigma = D eps. The element's nodal
// forces Ke u must then equal the consistent nodal forces of that stress, f_a = integral
// over the element boundary of N_a sigma.n (each edge gives h/2 sigma.n to both of its
// nodes). On the mesh, K u vanishes at interior nodes and equals the boundary traction
// times dx at the bottom/top rows. Rigid-body modes give zero force.
#include "dense_symmetric.hpp"
#include "verification_support.hpp"

#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/stencil.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace slipfront::fe {
namespace {

using verification::measure;

struct Stress {
  double s11, s22, s12;
};

// Plane-strain stress of the constant gradient G (G[i][k] = du_i/dx_k).
Stress stress_of(const Material& m, const double G[2][2]) {
  const double lambda = m.lame_lambda(), mu = m.shear_modulus();
  const double e11 = G[0][0], e22 = G[1][1], g12 = G[0][1] + G[1][0];
  return {(lambda + 2 * mu) * e11 + lambda * e22, lambda * e11 + (lambda + 2 * mu) * e22, mu * g12};
}

using Vec8 = std::array<double, 8>;

Vec8 mul(const ElementStiffness& K, const Vec8& u) {
  Vec8 f{};
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c)
      f[r] += K[r][c] * u[c];
  return f;
}

double max_abs(const Vec8& v) {
  double m = 0;
  for (double x : v)
    m = std::max(m, std::abs(x));
  return m;
}

double max_abs_diff(const Vec8& a, const Vec8& b) {
  double m = 0;
  for (int i = 0; i < 8; ++i)
    m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

TEST(ElementPatch, KeOfAnyLinearFieldGivesTheExactConstantStressNodalForces) {
  const Material mat;
  const ElementStiffness Ke = q4_plane_strain_stiffness(mat);
  // Several arbitrary gradients (not symmetric: rotations included) and element sizes.
  const double gradients[4][2][2] = {{{0.31, -0.17}, {0.05, 0.22}},
                                     {{1.0, 0.0}, {0.0, 0.0}},
                                     {{0.0, 0.7}, {-0.4, 0.0}},
                                     {{-0.2, 0.9}, {0.6, -1.3}}};
  double worst = 0;
  for (double h : {1.0, 0.37, 0.025}) {
    for (const auto& G : gradients) {
      const double c[2] = {0.123, -0.456}; // translation part: must not matter
      Vec8 u;
      for (int a = 0; a < 4; ++a) {
        const double x = h * kQ4NodeOffset[a][0], y = h * kQ4NodeOffset[a][1];
        u[2 * a] = c[0] + G[0][0] * x + G[0][1] * y;
        u[2 * a + 1] = c[1] + G[1][0] * x + G[1][1] * y;
      }
      const Stress s = stress_of(mat, G);
      // Outward normals of the two edges at each corner: bottom (0,-1), right (1,0),
      // top (0,1), left (-1,0). Traction t = sigma n.
      auto traction = [&](double n1, double n2) {
        return std::array<double, 2>{s.s11 * n1 + s.s12 * n2, s.s12 * n1 + s.s22 * n2};
      };
      const std::array<double, 2> bottom = traction(0, -1), right = traction(1, 0),
                                  top = traction(0, 1), left = traction(-1, 0);
      const std::array<std::array<double, 2>, 4> edges_of[4] = {
          {bottom, left}, {bottom, right}, {right, top}, {top, left}};
      Vec8 f;
      for (int a = 0; a < 4; ++a)
        for (int i = 0; i < 2; ++i)
          f[2 * a + i] = 0.5 * h * (edges_of[a][0][i] + edges_of[a][1][i]);
      const double err = max_abs_diff(mul(Ke, u), f) / max_abs(f);
      worst = std::max(worst, err);
      EXPECT_LT(err, 1e-13) << "h = " << h;
    }
  }
  measure("patch element linear fields: max |Ke u - f_exact| / |f| = %.3e", worst);
}

TEST(ElementPatch, KeIsSymmetricWithExactlyThreeRigidBodyZeroModes) {
  const Material mat;
  const ElementStiffness Ke = q4_plane_strain_stiffness(mat);
  double asym = 0, kmax = 0;
  verification::Dense D(8);
  for (int r = 0; r < 8; ++r)
    for (int c = 0; c < 8; ++c) {
      asym = std::max(asym, std::abs(Ke[r][c] - Ke[c][r]));
      kmax = std::max(kmax, std::abs(Ke[r][c]));
      D(r, c) = Ke[r][c];
    }
  asym /= kmax;
  EXPECT_LT(asym, 1e-15);

  const std::vector<double> ev = verification::jacobi_eigenvalues(D); // ascending
  const double largest = ev[7];
  for (int k = 0; k < 3; ++k)
    EXPECT_LT(std::abs(ev[k]) / largest, 1e-14) << "eigenvalue " << k;
  EXPECT_GT(ev[3] / largest, 1e-3) << "a fourth zero mode (hourglass) would mean under-integration";

  // Rigid modes: two translations and an (infinitesimal) rotation about an arbitrary point.
  double rigid = 0;
  for (int mode = 0; mode < 3; ++mode) {
    Vec8 u;
    for (int a = 0; a < 4; ++a) {
      const double x = kQ4NodeOffset[a][0] - 0.3, y = kQ4NodeOffset[a][1] + 0.8;
      u[2 * a] = mode == 0 ? 1.0 : mode == 2 ? -y : 0.0;
      u[2 * a + 1] = mode == 1 ? 1.0 : mode == 2 ? x : 0.0;
    }
    rigid = std::max(rigid, max_abs(mul(Ke, u)) / largest);
  }
  EXPECT_LT(rigid, 1e-14);

  // Full 2x2 Gauss integration is exact for the square Q4: the hourglass mode u1 = s xi eta
  // stores the exact energy u.Ke.u = 4/3 s^2 (lambda + 3 mu) (independent of h).
  Vec8 hg{};
  const double s = 0.7;
  const double xi_eta[4] = {1, -1, 1, -1};
  for (int a = 0; a < 4; ++a)
    hg[2 * a] = s * xi_eta[a];
  const double exact = 4.0 / 3.0 * s * s * (mat.lame_lambda() + 3 * mat.shear_modulus());
  const Vec8 Khg = mul(Ke, hg);
  double energy = 0;
  for (int i = 0; i < 8; ++i)
    energy += hg[i] * Khg[i];
  const double hg_err = std::abs(energy - exact) / exact;
  EXPECT_LT(hg_err, 1e-14);
  measure("patch element: asymmetry = %.3e, zero eigenvalues/max = %.3e %.3e %.3e, "
          "4th/max = %.4f, rigid force/max = %.3e, hourglass energy error = %.3e",
          asym, std::abs(ev[0]) / largest, std::abs(ev[1]) / largest, std::abs(ev[2]) / largest,
          ev[3] / largest, rigid, hg_err);
}

// K u on a periodic nx x ny mesh of element size dx for u = c + G x (G may be any
// gradient; with G[.][0] != 0 only the nodes away from the periodic seam see a linear field).
struct MeshPatch {
  double interior = 0, bottom = 0, top = 0; // max relative errors
};

MeshPatch mesh_patch(const double G[2][2], bool check_seam) {
  const Material mat;
  const MeshStencils st = build_stencils(q4_plane_strain_stiffness(mat));
  const int nx = 9, ny = 6;
  const double dx = 0.25;
  VectorField u(nx, ny), Ku(nx, ny);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double x = 1.7 + i * dx, y = j * dx;
      u.x.at(i, j) = 0.01 + G[0][0] * x + G[0][1] * y;
      u.y.at(i, j) = -0.02 + G[1][0] * x + G[1][1] * y;
    }
  u.x.refresh_all_ghosts();
  u.y.refresh_all_ghosts();
  apply_stiffness(st, u, Ku);
  const Stress s = stress_of(mat, G);
  // Force scale: the exact traction force, or the size of the stiffness terms for a
  // stress-free field (each term ~ E |u|, |u| ~ |G| dx + the 0.02 translation).
  double gmax = 0;
  for (int i = 0; i < 2; ++i)
    for (int k = 0; k < 2; ++k)
      gmax = std::max(gmax, std::abs(G[i][k]));
  const double scale = std::max({dx * std::abs(s.s11), dx * std::abs(s.s22), dx * std::abs(s.s12),
                                 mat.young_modulus * (gmax * dx + 0.02)});
  MeshPatch e;
  const int i0 = check_seam ? 0 : 1, i1 = check_seam ? nx : nx - 1;
  for (int j = 0; j < ny; ++j)
    for (int i = i0; i < i1; ++i) {
      // Exact: 0 inside; bottom: dx sigma.(0,-1); top: dx sigma.(0,1).
      const double sign = j == 0 ? -1.0 : j == ny - 1 ? 1.0 : 0.0;
      const double ex = sign * dx * s.s12, ey = sign * dx * s.s22;
      const double err =
          std::max(std::abs(Ku.x.at(i, j) - ex), std::abs(Ku.y.at(i, j) - ey)) / scale;
      double& slot = j == 0 ? e.bottom : j == ny - 1 ? e.top : e.interior;
      slot = std::max(slot, err);
    }
  return e;
}

TEST(MeshPatch, PeriodicCompatibleShearAndStretchGiveExactBoundaryTractions) {
  // u = (a x2, b x2): sigma12 = mu a, sigma22 = (lambda + 2 mu) b, sigma11 = lambda b.
  const double G[2][2] = {{0.0, 0.3}, {0.0, -0.2}};
  const MeshPatch e = mesh_patch(G, true);
  EXPECT_LT(e.interior, 1e-13);
  EXPECT_LT(e.bottom, 1e-13);
  EXPECT_LT(e.top, 1e-13);
  measure("patch mesh u=(a x2, b x2): rel. error interior %.3e, bottom %.3e, top %.3e", e.interior,
          e.bottom, e.top);
}

TEST(MeshPatch, AnyLinearFieldIsExactAwayFromThePeriodicSeam) {
  const double G[2][2] = {{0.11, -0.23}, {0.37, 0.05}};
  const MeshPatch e = mesh_patch(G, false);
  EXPECT_LT(e.interior, 1e-13);
  EXPECT_LT(e.bottom, 1e-13);
  EXPECT_LT(e.top, 1e-13);
  measure("patch mesh general G (off seam): rel. error interior %.3e, bottom %.3e, top %.3e",
          e.interior, e.bottom, e.top);
}

TEST(MeshPatch, RigidTranslationAndRotationGiveZeroForce) {
  const double translation[2][2] = {{0, 0}, {0, 0}};
  const MeshPatch t = mesh_patch(translation, true);
  EXPECT_LT(std::max({t.interior, t.bottom, t.top}), 1e-14);
  const double rotation[2][2] = {{0, -0.4}, {0.4, 0}};
  const MeshPatch r = mesh_patch(rotation, false);
  EXPECT_LT(std::max({r.interior, r.bottom, r.top}), 1e-13);
  measure("patch mesh rigid: translation force %.3e, rotation force %.3e (relative)",
          std::max({t.interior, t.bottom, t.top}), std::max({r.interior, r.bottom, r.top}));
}

} // namespace
} // namespace slipfront::fe
