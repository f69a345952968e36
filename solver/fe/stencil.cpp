#include "solver/fe/stencil.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace slipfront::fe {

MeshStencils build_stencils(const ElementStiffness& K) {
  // A node is local node `a` of the element whose lower-left node lies at -offset(a); its
  // neighbour `b` in that element lies at offset(b) - offset(a).
  auto add_element = [&](NodeStencil& s, int a) {
    for (int bn = 0; bn < 4; ++bn) {
      const int di = kQ4NodeOffset[bn][0] - kQ4NodeOffset[a][0];
      const int dj = kQ4NodeOffset[bn][1] - kQ4NodeOffset[a][1];
      Block2& blk = s.b[dj + 1][di + 1];
      blk.xx += K[2 * a][2 * bn];
      blk.xy += K[2 * a][2 * bn + 1];
      blk.yx += K[2 * a + 1][2 * bn];
      blk.yy += K[2 * a + 1][2 * bn + 1];
    }
  };
  MeshStencils s;
  // Elements above a node: the node is their local 0 or 1. Below: local 2 or 3.
  for (int a : {0, 1})
    add_element(s.bottom, a);
  for (int a : {2, 3})
    add_element(s.top, a);
  for (int a : {0, 1, 2, 3})
    add_element(s.interior, a);
  return s;
}

bool symmetric_form(const NodeStencil& s, SymmetricStencil& out) {
  const Block2(&b)[3][3] = s.b; // b[row + 1][column + 1]
  double largest = 0;
  for (const auto& row : b)
    for (const Block2& blk : row)
      largest = std::max(
          {largest, std::abs(blk.xx), std::abs(blk.xy), std::abs(blk.yx), std::abs(blk.yy)});
  const double tol = 1e-12 * largest;
  auto same = [&](double a, double c) { return std::abs(a - c) <= tol; };
  auto zero = [&](double a) { return std::abs(a) <= tol; };
  const Block2 &sw = b[0][0], &se = b[0][2], &nw = b[2][0], &ne = b[2][2];
  const Block2 &w = b[1][0], &e = b[1][2], &south = b[0][1], &north = b[2][1], &c = b[1][1];
  const bool corners = same(sw.xx, se.xx) && same(sw.xx, nw.xx) && same(sw.xx, ne.xx) &&
                       same(sw.yy, se.yy) && same(sw.yy, nw.yy) && same(sw.yy, ne.yy) &&
                       same(sw.xy, ne.xy) && same(sw.xy, -se.xy) && same(sw.xy, -nw.xy) &&
                       same(sw.yx, sw.xy) && same(ne.yx, ne.xy) && same(se.yx, se.xy) &&
                       same(nw.yx, nw.xy);
  const bool pairs =
      same(w.xx, e.xx) && same(w.yy, e.yy) && same(south.xx, north.xx) && same(south.yy, north.yy);
  bool no_cross = true; // no xy or yx term in the edge and centre blocks
  for (const Block2* blk : {&w, &e, &south, &north, &c})
    no_cross = no_cross && zero(blk->xy) && zero(blk->yx);
  if (!(corners && pairs && no_cross) || largest == 0) return false;
  out = {c.xx, w.xx, south.xx, sw.xx, c.yy, w.yy, south.yy, sw.yy, sw.xy};
  return true;
}

namespace {

// (K u)_i in the symmetric form (SymmetricStencil), from rows below (m), same (0), above (p).
struct NodeForce {
  double x, y;
};
inline NodeForce symmetric_node_force(const SymmetricStencil& k, const double* __restrict xm,
                                      const double* __restrict ym, const double* __restrict x0,
                                      const double* __restrict y0, const double* __restrict xp,
                                      const double* __restrict yp, int i) {
  // Corners: the diagonal pairs SW + NE and SE + NW, their sum and difference.
  const double x_a = xm[i - 1] + xp[i + 1], x_b = xm[i + 1] + xp[i - 1];
  const double y_a = ym[i - 1] + yp[i + 1], y_b = ym[i + 1] + yp[i - 1];
  const double kx = k.xx0 * x0[i] + k.xx_lr * (x0[i - 1] + x0[i + 1]) + k.xx_ud * (xm[i] + xp[i]) +
                    k.xx_c * (x_a + x_b) + k.d * (y_a - y_b);
  const double ky = k.yy0 * y0[i] + k.yy_lr * (y0[i - 1] + y0[i + 1]) + k.yy_ud * (ym[i] + yp[i]) +
                    k.yy_c * (y_a + y_b) + k.d * (x_a - x_b);
  return {kx, ky};
}

// (K u)_i of one node from the three rows, columns i-1, i, i+1.
inline NodeForce node_force(const StencilCoefficients& coef, const double* __restrict xm,
                            const double* __restrict ym, const double* __restrict x0,
                            const double* __restrict y0, const double* __restrict xp,
                            const double* __restrict yp, int i) {
  double kx = 0, ky = 0;
  for (int c = 0; c < 3; ++c) {
    const int k = i + c - 1;
    kx += coef.xx[0][c] * xm[k] + coef.xy[0][c] * ym[k] + coef.xx[1][c] * x0[k] +
          coef.xy[1][c] * y0[k] + coef.xx[2][c] * xp[k] + coef.xy[2][c] * yp[k];
    ky += coef.yx[0][c] * xm[k] + coef.yy[0][c] * ym[k] + coef.yx[1][c] * x0[k] +
          coef.yy[1][c] * y0[k] + coef.yx[2][c] * xp[k] + coef.yy[2][c] * yp[k];
  }
  return {kx, ky};
}

// v_i <- v_i - dt/m (K u)_i over a row, K u from force(xm, ym, x0, y0, xp, yp, i).
template <bool kEnergy, class Force>
void velocity_update(Force force, const double* __restrict uxm, const double* __restrict uym,
                     const double* __restrict ux0, const double* __restrict uy0,
                     const double* __restrict uxp, const double* __restrict uyp,
                     double* __restrict vx, double* __restrict vy, int nx, double dt, double mass,
                     double* __restrict kinetic, double* __restrict strain) {
  const double dt_over_m = dt / mass;
  for (int i = 0; i < nx; ++i) {
    const NodeForce f = force(uxm, uym, ux0, uy0, uxp, uyp, i);
    const double vx_new = vx[i] - dt_over_m * f.x;
    const double vy_new = vy[i] - dt_over_m * f.y;
    vx[i] = vx_new;
    vy[i] = vy_new;
    if constexpr (kEnergy) {
      kinetic[i] = vx_new * vx_new + vy_new * vy_new;
      strain[i] = f.x * (ux0[i] + dt * vx_new) + f.y * (uy0[i] + dt * vy_new);
    }
  }
}

// v_i <- v_i - dt/m (K w)_i with the damping's dissipation (stencil_damped_velocity_update).
template <bool kEnergy, class Force>
void damped_velocity_update(Force force, const double* __restrict uxm, const double* __restrict uym,
                            const double* __restrict ux0, const double* __restrict uy0,
                            const double* __restrict uxp, const double* __restrict uyp,
                            const double* __restrict wxm, const double* __restrict wym,
                            const double* __restrict wx0, const double* __restrict wy0,
                            const double* __restrict wxp, const double* __restrict wyp,
                            double* __restrict vx, double* __restrict vy, int nx, double dt,
                            double mass, double* __restrict dissipated, double* __restrict kinetic,
                            double* __restrict strain) {
  const double dt_over_m = dt / mass;
  for (int i = 0; i < nx; ++i) {
    const NodeForce ku = force(uxm, uym, ux0, uy0, uxp, uyp, i);
    const NodeForce kw = force(wxm, wym, wx0, wy0, wxp, wyp, i);
    const double vx_old = vx[i], vy_old = vy[i];
    const double vx_new = vx_old - dt_over_m * kw.x;
    const double vy_new = vy_old - dt_over_m * kw.y;
    vx[i] = vx_new;
    vy[i] = vy_new;
    dissipated[i] =
        0.5 * dt * ((vx_old + vx_new) * (kw.x - ku.x) + (vy_old + vy_new) * (kw.y - ku.y));
    if constexpr (kEnergy) {
      kinetic[i] = vx_new * vx_new + vy_new * vy_new;
      strain[i] = ku.x * (ux0[i] + dt * vx_new) + ku.y * (uy0[i] + dt * vy_new);
    }
  }
}

// Calls body(force) with the node force of `stencil`: the symmetric form if it has it.
template <class Body> void with_node_force(const NodeStencil& stencil, Body&& body) {
  SymmetricStencil k;
  if (symmetric_form(stencil, k)) {
    body([k](const double* __restrict xm, const double* __restrict ym, const double* __restrict x0,
             const double* __restrict y0, const double* __restrict xp, const double* __restrict yp,
             int i) { return symmetric_node_force(k, xm, ym, x0, y0, xp, yp, i); });
  } else {
    const StencilCoefficients coef(stencil);
    body([coef](const double* __restrict xm, const double* __restrict ym,
                const double* __restrict x0, const double* __restrict y0,
                const double* __restrict xp, const double* __restrict yp,
                int i) { return node_force(coef, xm, ym, x0, y0, xp, yp, i); });
  }
}

} // namespace

void stencil_damped_velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                                    const double* __restrict uym, const double* __restrict ux0,
                                    const double* __restrict uy0, const double* __restrict uxp,
                                    const double* __restrict uyp, const double* __restrict wxm,
                                    const double* __restrict wym, const double* __restrict wx0,
                                    const double* __restrict wy0, const double* __restrict wxp,
                                    const double* __restrict wyp, double* __restrict vx,
                                    double* __restrict vy, int nx, double dt, double mass,
                                    double* __restrict dissipated, double* __restrict kinetic,
                                    double* __restrict strain) {
  with_node_force(stencil, [&](auto force) {
    if (kinetic && strain)
      damped_velocity_update<true>(force, uxm, uym, ux0, uy0, uxp, uyp, wxm, wym, wx0, wy0, wxp,
                                   wyp, vx, vy, nx, dt, mass, dissipated, kinetic, strain);
    else
      damped_velocity_update<false>(force, uxm, uym, ux0, uy0, uxp, uyp, wxm, wym, wx0, wy0, wxp,
                                    wyp, vx, vy, nx, dt, mass, dissipated, nullptr, nullptr);
  });
}

namespace {

// velocity_update with the energy terms if both rows are given.
template <class Force>
void velocity_update_with(Force force, const double* __restrict uxm, const double* __restrict uym,
                          const double* __restrict ux0, const double* __restrict uy0,
                          const double* __restrict uxp, const double* __restrict uyp,
                          double* __restrict vx, double* __restrict vy, int nx, double dt,
                          double mass, double* __restrict kinetic, double* __restrict strain) {
  if (kinetic && strain)
    velocity_update<true>(force, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, kinetic,
                          strain);
  else
    velocity_update<false>(force, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, nullptr,
                           nullptr);
}

} // namespace

void symmetric_velocity_update(const SymmetricStencil& k, const double* __restrict uxm,
                               const double* __restrict uym, const double* __restrict ux0,
                               const double* __restrict uy0, const double* __restrict uxp,
                               const double* __restrict uyp, double* __restrict vx,
                               double* __restrict vy, int nx, double dt, double mass,
                               double* __restrict kinetic, double* __restrict strain) {
  auto force = [&k](const double* __restrict xm, const double* __restrict ym,
                    const double* __restrict x0, const double* __restrict y0,
                    const double* __restrict xp, const double* __restrict yp,
                    int i) { return symmetric_node_force(k, xm, ym, x0, y0, xp, yp, i); };
  velocity_update_with(force, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, kinetic, strain);
}

void stencil_velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                             const double* __restrict uym, const double* __restrict ux0,
                             const double* __restrict uy0, const double* __restrict uxp,
                             const double* __restrict uyp, double* __restrict vx,
                             double* __restrict vy, int nx, double dt, double mass,
                             double* __restrict kinetic, double* __restrict strain) {
  with_node_force(stencil, [&](auto force) {
    velocity_update_with(force, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, kinetic,
                         strain);
  });
}

void stencil_force_row(const NodeStencil& stencil, const double* __restrict uxm,
                       const double* __restrict uym, const double* __restrict ux0,
                       const double* __restrict uy0, const double* __restrict uxp,
                       const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                       int nx) {
  const StencilCoefficients k(stencil);
  for (int i = 0; i < nx; ++i) {
    double kx = 0, ky = 0;
    for (int c = 0; c < 3; ++c) { // columns i-1, i, i+1 of the rows below, same, above
      kx += k.xx[0][c] * uxm[i + c - 1] + k.xy[0][c] * uym[i + c - 1] +
            k.xx[1][c] * ux0[i + c - 1] + k.xy[1][c] * uy0[i + c - 1] +
            k.xx[2][c] * uxp[i + c - 1] + k.xy[2][c] * uyp[i + c - 1];
      ky += k.yx[0][c] * uxm[i + c - 1] + k.yy[0][c] * uym[i + c - 1] +
            k.yx[1][c] * ux0[i + c - 1] + k.yy[1][c] * uy0[i + c - 1] +
            k.yx[2][c] * uxp[i + c - 1] + k.yy[2][c] * uyp[i + c - 1];
    }
    fx[i] = kx;
    fy[i] = ky;
  }
}

void symmetric_force_row(const SymmetricStencil& k, const double* __restrict uxm,
                         const double* __restrict uym, const double* __restrict ux0,
                         const double* __restrict uy0, const double* __restrict uxp,
                         const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                         int nx) {
  const SymmetricStencil c = k;
  for (int i = 0; i < nx; ++i) {
    const NodeForce f = symmetric_node_force(c, uxm, uym, ux0, uy0, uxp, uyp, i);
    fx[i] = f.x;
    fy[i] = f.y;
  }
}

bool has_no_cross_terms(const NodeStencil& stencil) {
  for (const auto& row : stencil.b)
    for (const Block2& blk : row)
      if (blk.xy != 0 || blk.yx != 0) return false;
  return true;
}

void uncoupled_force_row(const NodeStencil& stencil, const double* __restrict uxm,
                         const double* __restrict uym, const double* __restrict ux0,
                         const double* __restrict uy0, const double* __restrict uxp,
                         const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                         int nx) {
  const StencilCoefficients k(stencil);
  for (int i = 0; i < nx; ++i) {
    double kx = 0, ky = 0;
    for (int c = 0; c < 3; ++c) {
      kx += k.xx[0][c] * uxm[i + c - 1] + k.xx[1][c] * ux0[i + c - 1] + k.xx[2][c] * uxp[i + c - 1];
      ky += k.yy[0][c] * uym[i + c - 1] + k.yy[1][c] * uy0[i + c - 1] + k.yy[2][c] * uyp[i + c - 1];
    }
    fx[i] = kx;
    fy[i] = ky;
  }
}

void apply_stiffness(const MeshStencils& stencils, const VectorField& u, VectorField& Ku) {
  const int nx = u.x.nx(), ny = u.x.ny();
  const std::vector<double> zero(nx + 2, 0.0);
  const double* z = zero.data() + 1;
  for (int j = 0; j < ny; ++j) {
    const NodeStencil& s = (j == 0)        ? stencils.bottom
                           : (j == ny - 1) ? stencils.top
                                           : stencils.interior;
    const double* uxm = j > 0 ? u.x.row(j - 1) : z;
    const double* uym = j > 0 ? u.y.row(j - 1) : z;
    const double* uxp = j < ny - 1 ? u.x.row(j + 1) : z;
    const double* uyp = j < ny - 1 ? u.y.row(j + 1) : z;
    double* kx = Ku.x.row(j);
    double* ky = Ku.y.row(j);
    for_each_node_force(s, uxm, uym, u.x.row(j), u.y.row(j), uxp, uyp, nx,
                        [&](int i, double fx, double fy) {
                          kx[i] = fx;
                          ky[i] = fy;
                        });
  }
}

} // namespace slipfront::fe
