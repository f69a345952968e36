// The perfectly matched layer on top of a block (geometry.top_boundary "pml"): rows above the
// elastic region in which x2 is stretched, so that waves enter the layer without reflection
// and decay in it; its last row carries the Lysmer-Kuhlemeyer dashpots (docs/physics.md
// "Perfectly matched layer").
//
// The complex-frequency-shifted stretch s(x2) = 1 + d(x2) / (alpha + i omega) (Kuzuoglu &
// Mittra 1996; Komatitsch & Martin 2007, Geophysics 72, SM155) of x2 alone, in the Galerkin
// form of the second-order elastic equations (the directional split of Basu & Chopra 2003,
// CMAME 192, 1337, with the damping taken at the node):
//   M (s (i omega)^2) u = -(s K_11 + K_12 + K_21 + K_22 / s) u,
// K_aa the stiffness of the derivatives along x_a alone (element_stiffness.hpp). In time, with
// the memory fields zeta (zeta' = u - alpha zeta) and, per element, phi
// (phi' = d K_22 u - (alpha + d) phi):
//   M (u'' + d u' - d alpha u + d alpha^2 zeta) = -(K u + sum_e d_e K_11^e zeta - sum_e phi_e).
// d = 0 outside the layer, where this is the plain scheme. The profile
//   d(x2) = d0 (x / H)^2,  d0 = 3 c_p ln(1 / R0) / (2 H),
// x the depth into the layer of thickness H (Collino & Tsogka 2001, Geophysics 66, 294):
// R0 is the reflection of a normally incident P wave after its round trip in the continuum.
#pragma once

#include "solver/fe/nodal_field.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/params.hpp"

#include <vector>

namespace slipfront::fe {

// R0 of the profile, and alpha = kLayerFrequencyShift * d0.
inline constexpr double kLayerDesignReflection = 1e-3;
inline constexpr double kLayerFrequencyShift = 0.0;

class AbsorbingLayer {
public:
  AbsorbingLayer() = default; // no layer
  // A layer of `rows` element rows at the top of a block of nx x ny nodes: rows
  // ny - 1 - rows (d = 0, the end of the elastic region) to ny - 1 (d = d0).
  AbsorbingLayer(const Material& material, int nx, int ny, int rows, double dx);

  int rows() const { return rows_; }
  int first_row() const { return first_; }
  // Rows whose velocity takes the layer's terms: the first row (d = 0 at the node, but the
  // elements above it are in the layer) and those above it.
  bool damps_row(int j) const { return rows_ > 0 && j >= first_; }
  double damping(int j) const;         // d of the nodes of row j [1/s]
  double element_damping(int e) const; // d of the elements between rows e and e + 1
  double max_damping() const { return d0_; }
  double frequency_shift() const { return alpha_; }
  void set_time_step(double dt) { dt_ = dt; }

  // The velocity of row j (damps_row(j)), whole, from u, zeta and phi at t_n:
  //   v^{n+1/2} (1 + b) = v^{n-1/2} (1 - b) - dt/m f,  b = (m d + c) dt / (2 m),
  // f = K u + extra + sum_e (d_e K_11^e zeta - phi_e) + m d (alpha^2 zeta - alpha u), over the
  // elements e above and below the node, c the dashpot of the
  // far row (0 below it), `extra` another force (the mesh damping's) or null; phi, kept at
  // the half steps, is advanced. Returns the row's energy terms: the work of every force but K u as
  // dissipated.
  struct RowEnergy {
    double kinetic = 0, strain = 0, dissipated = 0;
  };
  // `symmetric`: the stiffness in its symmetric form, if it has one (else null).
  RowEnergy velocity_row(int j, const NodeStencil& stiffness, const SymmetricStencil* symmetric,
                         const VectorField& u, VectorField& v, const double* extra_x,
                         const double* extra_y, double mass, double dashpot_x, double dashpot_y,
                         bool energy);
  // zeta of row j >= first_row() after its u reached t_{n+1} (v is v^{n+1/2}).
  void advance_memory_row(int j, const VectorField& u, const VectorField& v);

private:
  int nx_ = 0, ny_ = 0, rows_ = 0, first_ = 0;
  double d0_ = 0, alpha_ = 0, dt_ = 0;
  MeshStencils k11_, k22_;
  std::vector<NodeStencil> k11_rows_; // per row: d_above K_11^above + d_below K_11^below
  // Rows first_ .. ny - 1, at index j - first_: zeta, and phi of the elements above and below.
  VectorField zeta_, phi_above_, phi_below_;
  std::vector<double> zero_row_;
};

} // namespace slipfront::fe
