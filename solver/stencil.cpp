#include "solver/stencil.hpp"

#include <vector>

namespace slipfront {

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

namespace {

template <bool kEnergy>
void velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                     const double* __restrict uym, const double* __restrict ux0,
                     const double* __restrict uy0, const double* __restrict uxp,
                     const double* __restrict uyp, double* __restrict vx, double* __restrict vy,
                     int nx, double dt, double mass, double* __restrict kinetic,
                     double* __restrict strain) {
  const StencilCoefficients coef(stencil);
  const double dt_over_m = dt / mass;
  for (int i = 0; i < nx; ++i) {
    double kx = 0, ky = 0;
    for (int c = 0; c < 3; ++c) { // columns i-1, i, i+1 of the rows below, same and above
      const int k = i + c - 1;
      kx += coef.xx[0][c] * uxm[k] + coef.xy[0][c] * uym[k] + coef.xx[1][c] * ux0[k] +
            coef.xy[1][c] * uy0[k] + coef.xx[2][c] * uxp[k] + coef.xy[2][c] * uyp[k];
      ky += coef.yx[0][c] * uxm[k] + coef.yy[0][c] * uym[k] + coef.yx[1][c] * ux0[k] +
            coef.yy[1][c] * uy0[k] + coef.yx[2][c] * uxp[k] + coef.yy[2][c] * uyp[k];
    }
    const double vx_new = vx[i] - dt_over_m * kx;
    const double vy_new = vy[i] - dt_over_m * ky;
    vx[i] = vx_new;
    vy[i] = vy_new;
    if constexpr (kEnergy) {
      kinetic[i] = vx_new * vx_new + vy_new * vy_new;
      strain[i] = kx * (ux0[i] + dt * vx_new) + ky * (uy0[i] + dt * vy_new);
    }
  }
}

// (K u)_i of one node from the three rows, columns i-1, i, i+1.
struct NodeForce {
  double x, y;
};
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

template <bool kEnergy>
void damped_velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                            const double* __restrict uym, const double* __restrict ux0,
                            const double* __restrict uy0, const double* __restrict uxp,
                            const double* __restrict uyp, const double* __restrict wxm,
                            const double* __restrict wym, const double* __restrict wx0,
                            const double* __restrict wy0, const double* __restrict wxp,
                            const double* __restrict wyp, double* __restrict vx,
                            double* __restrict vy, int nx, double dt, double mass,
                            double* __restrict dissipated, double* __restrict kinetic,
                            double* __restrict strain) {
  const StencilCoefficients coef(stencil);
  const double dt_over_m = dt / mass;
  for (int i = 0; i < nx; ++i) {
    const NodeForce ku = node_force(coef, uxm, uym, ux0, uy0, uxp, uyp, i);
    const NodeForce kw = node_force(coef, wxm, wym, wx0, wy0, wxp, wyp, i);
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
  if (kinetic && strain)
    damped_velocity_update<true>(stencil, uxm, uym, ux0, uy0, uxp, uyp, wxm, wym, wx0, wy0, wxp,
                                 wyp, vx, vy, nx, dt, mass, dissipated, kinetic, strain);
  else
    damped_velocity_update<false>(stencil, uxm, uym, ux0, uy0, uxp, uyp, wxm, wym, wx0, wy0, wxp,
                                  wyp, vx, vy, nx, dt, mass, dissipated, nullptr, nullptr);
}

void stencil_velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                             const double* __restrict uym, const double* __restrict ux0,
                             const double* __restrict uy0, const double* __restrict uxp,
                             const double* __restrict uyp, double* __restrict vx,
                             double* __restrict vy, int nx, double dt, double mass,
                             double* __restrict kinetic, double* __restrict strain) {
  if (kinetic && strain)
    velocity_update<true>(stencil, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, kinetic,
                          strain);
  else
    velocity_update<false>(stencil, uxm, uym, ux0, uy0, uxp, uyp, vx, vy, nx, dt, mass, nullptr,
                           nullptr);
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

} // namespace slipfront
