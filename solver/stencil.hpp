// The stiffness of the regular mesh as a 9-point nodal stencil (matrix-free).
//
// Every element is alike, so the row of the global stiffness matrix K belonging to a node
// is the sum of the element stiffness blocks of the (up to four) elements around it. The
// result is a 3x3 stencil of 2x2 blocks: (K u)_node = sum over neighbours of B * u_nb.
// Interface (bottom) and top nodes only have the elements above/below them, so there are
// three stencils. The neighbour rows missing at a boundary get zero blocks.
#pragma once

#include "solver/element_stiffness.hpp"
#include "solver/nodal_field.hpp"

namespace slipfront {

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

// Contribution of one neighbour row (blocks b[0..2] for columns i-1, i, i+1) to (K u)_i.
inline void add_stencil_row(const Block2 (&b)[3], const double* __restrict ux,
                            const double* __restrict uy, int i, double& kx, double& ky) {
  kx += b[0].xx * ux[i - 1] + b[0].xy * uy[i - 1] + b[1].xx * ux[i] + b[1].xy * uy[i] +
        b[2].xx * ux[i + 1] + b[2].xy * uy[i + 1];
  ky += b[0].yx * ux[i - 1] + b[0].yy * uy[i - 1] + b[1].yx * ux[i] + b[1].yy * uy[i] +
        b[2].yx * ux[i + 1] + b[2].yy * uy[i + 1];
}

// (K u) at every node i of one row, handed to visit(i, kx, ky). The rows below/above may be
// any row (e.g. a zero row) where the stencil's blocks for them are zero. Reads the ghost
// nodes of the three rows: they must be current.
template <class Visit>
inline void for_each_node_force(const NodeStencil& s, const double* __restrict uxm,
                                const double* __restrict uym, const double* __restrict ux0,
                                const double* __restrict uy0, const double* __restrict uxp,
                                const double* __restrict uyp, int nx, Visit&& visit) {
  for (int i = 0; i < nx; ++i) {
    double kx = 0, ky = 0;
    add_stencil_row(s.b[0], uxm, uym, i, kx, ky); // row below
    add_stencil_row(s.b[1], ux0, uy0, i, kx, ky); // same row
    add_stencil_row(s.b[2], uxp, uyp, i, kx, ky); // row above
    visit(i, kx, ky);
  }
}

// K u over the whole mesh (not the fast path: used by the stable time step estimate and
// by tests). u's ghosts must be current; result has the layout of u (ghosts not set).
void apply_stiffness(const MeshStencils& stencils, const VectorField& u, VectorField& Ku);

} // namespace slipfront
