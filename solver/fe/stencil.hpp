// The stiffness of the regular mesh as a 9-point nodal stencil (matrix-free).
//
// Every element is alike, so the row of the global stiffness matrix K belonging to a node
// is the sum of the element stiffness blocks of the (up to four) elements around it. The
// result is a 3x3 stencil of 2x2 blocks: (K u)_node = sum over neighbours of B * u_nb.
// Interface (bottom) and top nodes only have the elements above/below them, so there are
// three stencils. The neighbour rows missing at a boundary get zero blocks.
#pragma once

#include "solver/fe/element_stiffness.hpp"
#include "solver/fe/nodal_field.hpp"

namespace slipfront::fe {

struct Block2 {
  double xx = 0, xy = 0, yx = 0, yy = 0; // (K u)_x = xx u_x + xy u_y; (K u)_y = yx u_x + yy u_y
};

struct NodeStencil {
  Block2 b[3][3]; // b[dj + 1][di + 1]: neighbour at column offset di, row offset dj
};

struct MeshStencils {
  NodeStencil bottom, interior, top;
};

MeshStencils build_stencils(const ElementStiffness& K);

// A stencil as four 3x3 coefficient arrays [row offset + 1][column offset + 1]. Hot loops
// take a local copy: the compiler then knows the coefficients cannot alias the fields the
// loop writes, keeps them in registers, and vectorises the loop.
struct StencilCoefficients {
  double xx[3][3], xy[3][3], yx[3][3], yy[3][3];
  explicit StencilCoefficients(const NodeStencil& s) {
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) {
        xx[r][c] = s.b[r][c].xx;
        xy[r][c] = s.b[r][c].xy;
        yx[r][c] = s.b[r][c].yx;
        yy[r][c] = s.b[r][c].yy;
      }
  }
};

// The interior stencil of the regular mesh has the symmetries of the square element: the
// four corner blocks share their diagonal terms and carry the off-diagonal term with
// alternating sign, the left/right and below/above pairs are equal and have no off-diagonal
// term, nor has the centre. Written with these, K u takes 10 multiplications and 12
// additions per node instead of 36 fused multiply-adds (docs/performance.md §3b):
//   (K u)_x = xx0 u_x + xx_lr (u_x,W + u_x,E) + xx_ud (u_x,S + u_x,N) + xx_c sum_corners u_x
//           + d ((u_y,SW + u_y,NE) - (u_y,SE + u_y,NW)),
// the same with x and y exchanged for (K u)_y. The same stencil up to the rounding of its
// assembly (the terms that are zero come out as 1e-17 of the others), so its sums round
// differently in the last bits: tests/solver/fe/stencil_symmetry_test.cpp bounds that.
struct SymmetricStencil {
  double xx0, xx_lr, xx_ud, xx_c; // (K u)_x from u_x: centre, left/right, below/above, corners
  double yy0, yy_lr, yy_ud, yy_c; // (K u)_y from u_y
  double d;                       // the xy (= yx) term of the lower-left corner block
};

// `s` in the symmetric form, if it has it to a relative 1e-12 of its largest term (the
// interior stencil has it; the bottom and top stencils, one row missing, do not).
bool symmetric_form(const NodeStencil& s, SymmetricStencil& out);

// (K u) at every node i of one row, handed to visit(i, kx, ky). The rows below/above may be
// any row (e.g. a zero row) where the stencil's blocks for them are zero. Reads the ghost
// nodes of the three rows: they must be current.
template <class Visit>
inline void for_each_node_force(const NodeStencil& stencil, const double* __restrict uxm,
                                const double* __restrict uym, const double* __restrict ux0,
                                const double* __restrict uy0, const double* __restrict uxp,
                                const double* __restrict uyp, int nx, Visit&& visit) {
  const StencilCoefficients coef(stencil);
  const double* ux[3] = {uxm, ux0, uxp}; // rows below, same, above
  const double* uy[3] = {uym, uy0, uyp};
  for (int i = 0; i < nx; ++i) {
    double kx = 0, ky = 0;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c) { // columns i-1, i, i+1
        const double u1 = ux[r][i + c - 1], u2 = uy[r][i + c - 1];
        kx += coef.xx[r][c] * u1 + coef.xy[r][c] * u2;
        ky += coef.yx[r][c] * u1 + coef.yy[r][c] * u2;
      }
    visit(i, kx, ky);
  }
}

// The hot loop of a step, for a bulk (or top) row without dashpots:
//   v_i <- v_i - dt/m (K u)_i,
// with K u in the symmetric form if the stencil has it (the bulk rows), else as written.
// Written without the visitor so that the compiler sees every pointer as restrict and
// vectorises it. If `kinetic` and `strain` are not null, it also writes each node's energy
// terms v_i.v_i and (K u)_i.(u_i + dt v_i) there (summed by the caller in a fixed order).
void stencil_velocity_update(const NodeStencil& stencil, const double* __restrict uxm,
                             const double* __restrict uym, const double* __restrict ux0,
                             const double* __restrict uy0, const double* __restrict uxp,
                             const double* __restrict uyp, double* __restrict vx,
                             double* __restrict vy, int nx, double dt, double mass,
                             double* __restrict kinetic = nullptr,
                             double* __restrict strain = nullptr);

// The same with the symmetric form given (the caller found it once with symmetric_form).
void symmetric_velocity_update(const SymmetricStencil& k, const double* __restrict uxm,
                               const double* __restrict uym, const double* __restrict ux0,
                               const double* __restrict uy0, const double* __restrict uxp,
                               const double* __restrict uyp, double* __restrict vx,
                               double* __restrict vy, int nx, double dt, double mass,
                               double* __restrict kinetic = nullptr,
                               double* __restrict strain = nullptr);

// The same update with the mesh-scale damping force -a K v^{n-1/2} (docs/physics.md), from
// w = u + a v^{n-1/2} kept beside u: v_i <- v_i - dt/m (K w)_i. Writes each node's damping
// dissipation over the step, dt v_mid.(K w - K u)_i with v_mid = (v^{n-1/2} + v^{n+1/2})/2,
// to `dissipated` (always); the energy terms as stencil_velocity_update, with K u.
void stencil_damped_velocity_update(
    const NodeStencil& stencil, const double* __restrict uxm, const double* __restrict uym,
    const double* __restrict ux0, const double* __restrict uy0, const double* __restrict uxp,
    const double* __restrict uyp, const double* __restrict wxm, const double* __restrict wym,
    const double* __restrict wx0, const double* __restrict wy0, const double* __restrict wxp,
    const double* __restrict wyp, double* __restrict vx, double* __restrict vy, int nx, double dt,
    double mass, double* __restrict dissipated, double* __restrict kinetic = nullptr,
    double* __restrict strain = nullptr);

// (K u) of one row into fx, fy: for_each_node_force written so that it vectorises.
void stencil_force_row(const NodeStencil& stencil, const double* __restrict uxm,
                       const double* __restrict uym, const double* __restrict ux0,
                       const double* __restrict uy0, const double* __restrict uxp,
                       const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                       int nx);

// The same with the symmetric form given.
void symmetric_force_row(const SymmetricStencil& k, const double* __restrict uxm,
                         const double* __restrict uym, const double* __restrict ux0,
                         const double* __restrict uy0, const double* __restrict uxp,
                         const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                         int nx);

// The same for a stencil without xy and yx terms (the directional parts K_11 and K_22 of the
// perfectly matched layer: has_no_cross_terms), half the arithmetic.
bool has_no_cross_terms(const NodeStencil& stencil);
void uncoupled_force_row(const NodeStencil& stencil, const double* __restrict uxm,
                         const double* __restrict uym, const double* __restrict ux0,
                         const double* __restrict uy0, const double* __restrict uxp,
                         const double* __restrict uyp, double* __restrict fx, double* __restrict fy,
                         int nx);

// K u over the whole mesh (not the fast path: used by the stable time step estimate and
// by tests). u's ghosts must be current; result has the layout of u (ghosts not set).
void apply_stiffness(const MeshStencils& stencils, const VectorField& u, VectorField& Ku);

} // namespace slipfront::fe
