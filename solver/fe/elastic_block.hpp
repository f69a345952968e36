// One elastic block of the FE mesh: a regular Q4 mesh of nx x ny nodes with its material,
// its state (u, v and, with the mesh damping, w = u + a v) and its row work in a step
// (solver/fe/mesh_stepper.hpp steps one block, or two at an interface between two solids).
//
// Row 0 is the interface row, row ny - 1 the far boundary: it keeps its remote traction
// (free for the perturbation) or absorbs waves. The upper solid is a block as it stands
// (x2 = j dx); the lower solid is a block in its mirrored frame y' = -x2 (row j at
// x2 = -j dx), where u'_2 = -u_2 and F'_2 = -F_2: an isotropic square mesh is there the same
// mesh with the same element stiffness (docs/physics.md "Two solids"). A block knows
// nothing of the interface law: the mesh stepper reads its interface row's forces
// (begin_interface_row) and writes the row's velocities.
#pragma once

#include "solver/fe/absorbing_layer.hpp"
#include "solver/fe/nodal_field.hpp"
#include "solver/fe/quiet_columns.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/params.hpp"

#include <vector>

namespace slipfront::fe {

// What one step leaves behind in a block until the step is summed up (per row, in row order).
struct BlockStepRecord {
  bool compute_energy = false;
  std::vector<double> row_kinetic, row_strain, row_dissipated;
  long long swept = 0; // node updates made
  void reset(int rows, bool energy);
};

class ElasticBlock {
public:
  // `far`: the boundary condition of row ny - 1; `mesh_damping`: zeta of params.fe;
  // `layer_rows`: with far = pml, the rows of the perfectly matched layer at the top of the
  // ny rows (the elastic region is the ny - layer_rows rows below).
  ElasticBlock(const Material& material, int nx, int ny, double dx, TopBoundary far,
               double mesh_damping, int layer_rows = 0);

  // The block's own stable step (damped if the damping is on), and the step the run takes.
  double stable_dt() const { return stable_dt_; }
  void set_time_step(double dt) {
    dt_ = dt;
    layer_.set_time_step(dt);
  }

  // Row step r >= 1 of a step (solver/fe/level_pipeline.hpp): v of row r from u of rows
  // r-1, r, r+1 (if r < ny), then u of row r-1 from its new v. Nothing beyond r = ny.
  void row_step(BlockStepRecord& record, int r, std::vector<double>& scratch);
  // Row step 0 up to the interface law: the row is swept whole; K u of the row and the
  // damping force a K v^{n-1/2} (if damped) are then in interface_stiffness_*() and
  // interface_damping_*(). The caller writes the row's new velocities and its row-0 terms.
  void begin_interface_row(BlockStepRecord& record);
  // After a trip of steps (MeshStepper::advance): the highest row that may be non-zero.
  void finish_trip();

  const double* interface_stiffness_x() const { return kx0_.data(); }
  const double* interface_stiffness_y() const { return ky0_.data(); }
  const double* interface_damping_x() const { return kdx_.data(); } // damped() only
  const double* interface_damping_y() const { return kdy_.data(); }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double dx() const { return dx_; }
  double height() const { return (ny_ - 1 - layer_.rows()) * dx_; } // without the layer
  const AbsorbingLayer& layer() const { return layer_; }
  const Material& material() const { return material_; }
  TopBoundary far_boundary() const { return far_; }
  bool damped() const { return damping_a_ > 0; }
  double damping_coefficient() const { return damping_a_; } // a [s]
  double node_mass(int j) const;                            // lumped mass of a node of row j [kg/m]
  int active_rows() const { return active_rows_; }

  const VectorField& displacement() const { return u_; }
  const VectorField& velocity() const { return v_; }
  VectorField& displacement() { return u_; } // for verification set-ups and the interface row
  VectorField& velocity() { return v_; }
  // Mark every row as possibly non-zero (after a test wrote initial fields by hand); with
  // the mesh damping on, also recomputes w = u + a v from them.
  void activate_all_rows();
  void set_skip_quiet(bool on) { skip_quiet_ = on; }
  ColumnRange active_columns(int j) const { return columns_[j]; }

private:
  // The velocity part for the absorbing far row and the damped rows.
  void velocity_row(BlockStepRecord& record, int j, ColumnRange cols, std::vector<double>& scratch);
  // A bulk row's velocity and the displacement of the row below, block of columns by block.
  void bulk_row_step(BlockStepRecord& record, int r, ColumnRange cols,
                     std::vector<double>& scratch);
  // v of bulk row r (undamped) on columns [begin, begin + n); energy terms if kin, str.
  void bulk_velocity(int r, int begin, int n, double* kin, double* str);
  void finish_displacement_row(int j); // ghosts and quiet-column range of row j after its u
  // The columns of row j this step sweeps, from the ranges of rows j-1, j, j+1.
  ColumnRange sweep_columns(int j) const;
  void absorbing_far_row(BlockStepRecord& record);
  void damped_interior_row(BlockStepRecord& record, int j, const NodeStencil& s, ColumnRange cols,
                           std::vector<double>& scratch);
  // K w - K u (= a K v^{n-1/2}) of the row j into dx, dy, from the rows of u and w.
  void damping_force_row(const NodeStencil& s, int j, double* dx, double* dy) const;
  void update_displacement_row(int j); // advance_displacement on its columns, then finish
  void advance_displacement(int j, int begin, int end); // u += dt v (and w) on [begin, end)
  void update_damping_row(int j);                       // w = u + a v on row j, with its ghosts
  // Row j's kinetic and strain energy from its per-node terms, summed in node order.
  void store_row_energy(BlockStepRecord& record, int j, const double* kin, const double* str,
                        int count) const;
  // Dashpots on the far row: the absorbing top, and the end of the perfectly matched layer.
  bool absorbing_far() const { return far_ == TopBoundary::absorbing || far_ == TopBoundary::pml; }
  void layer_row(BlockStepRecord& record, int j, std::vector<double>& scratch);

  Material material_;
  int nx_, ny_;
  double dx_;
  TopBoundary far_;
  double stable_dt_ = 0, dt_ = 0;
  MeshStencils stencils_;
  SymmetricStencil interior_form_;  // the interior stencil in its symmetric form ...
  bool interior_symmetric_ = false; // ... if it has one (solver/fe/stencil.hpp)
  VectorField u_, v_;
  double damping_a_ = 0;          // a = zeta dx / c_s [s]; 0: undamped, w_ unused
  VectorField w_;                 // u + a v^{n-1/2}, with the damping on
  std::vector<double> kdx_, kdy_; // damping force row of the interface
  // ... and of the absorbing far row: a row of its own, another thread may be on the interface.
  std::vector<double> kdx_far_, kdy_far_;
  std::vector<double> zero_row_;  // nx + 2 zeros, a neighbour for boundary rows
  std::vector<double> kx0_, ky0_; // K u on the interface row
  int active_rows_ = 1;           // rows >= active_rows_ hold exact zeros in u and v
  bool skip_quiet_ = true;
  std::vector<ColumnRange> columns_;      // per row: u and v are exact zeros outside
  std::vector<ColumnRange> next_columns_; // per row: the columns its current step sweeps
  AbsorbingLayer layer_;                  // rows 0 without the perfectly matched layer
};

} // namespace slipfront::fe
