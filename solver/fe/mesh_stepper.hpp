// The FE method's mesh stepper: a regular Q4 mesh of the block on the rigid plane, its
// state, and one explicit central-difference step (the RuptureMethod around it:
// solver/fe/finite_element_method.hpp).
//
// Perturbation formulation: u, v are the displacement and velocity on top of the uniform,
// stuck, pre-stressed initial state. The top keeps its remote traction, so it is free for
// the perturbation (or absorbing). At an interface node the plane exerts the total force
// C = (C1, C2); in the initial state C0_i = dx (-tau0_i, |sigma0_i|) (the node's initial
// stresses, solver/interface/interface_parameters.hpp), so the perturbation sees C - C0 (the
// release of the pre-stress when the node slips or opens).
//
// Central differences (explicit Newmark beta = 0, gamma = 1/2) in leapfrog form:
//   v^{n+1/2} = v^{n-1/2} + dt M^-1 (F^n - K u^n),   u^{n+1} = u^n + dt v^{n+1/2},
// with M lumped. The stored velocity is that of the last half step.
//
// Several steps can be taken as one block (advance): the rows are swept once for all of
// them, each step two rows behind the one before (solver/fe/level_pipeline.hpp), with the same
// bits as stepping one at a time.
//
// Optional mesh-scale damping (params.fe.mesh_damping = zeta > 0, docs/physics.md): a
// stiffness-proportional (Kelvin-Voigt) force -a K v with a = zeta dx / c_s, taken at the
// last half step's velocity v^{n-1/2} so that the step stays explicit:
//   v^{n+1/2} = v^{n-1/2} + dt M^-1 (F^n - K (u^n + a v^{n-1/2})).
// w = u + a v is kept beside u (advanced with it, row by row), so K w comes from the same
// stencil pass as K u. The stable step shrinks to sqrt(a^2 + dt0^2) - a
// (damped_stable_time_step); the damping's work goes into the dissipated energy.
#pragma once

#include "solver/fe/nodal_field.hpp"
#include "solver/fe/quiet_columns.hpp"
#include "solver/fe/stencil.hpp"
#include "solver/interface/interface_fields.hpp"
#include "solver/interface/interface_law.hpp"
#include "solver/interface/interface_parameters.hpp"
#include "solver/params.hpp"
#include "solver/thread_team.hpp"

#include <vector>

namespace slipfront::fe {

class MeshStepper {
public:
  explicit MeshStepper(const SimulationParams& params);

  // Advance from t_n to t_{n+1}. With compute_energy the kinetic and strain terms of the
  // energy balance are evaluated in the same sweep (else they keep their last value).
  void step(ThreadTeam& team, bool compute_energy);
  // Advance energy_steps.size() steps as one block (temporal blocking over the team's
  // threads); energy_steps[k]: evaluate the energy terms in step k of the block. The same
  // bits as that many step() calls. After it, interface_after(k) and energy_after(k) are
  // those after step k of the block; interface() and energy() those after the last.
  void advance(ThreadTeam& team, const std::vector<bool>& energy_steps);
  const InterfaceFields& interface_after(int k) const { return levels_[k].iface; }
  const EnergyBalance& energy_after(int k) const { return levels_[k].energy; }

  int nx() const { return nx_; }
  int ny() const { return ny_; }
  double dx() const { return dx_; }
  double height() const { return height_; }
  double dt() const { return dt_; }
  double stable_dt() const { return stable_dt_; }
  long steps_done() const { return step_; }
  double time() const { return step_ * dt_; } // t_n of the state (u^n)
  int active_rows() const { return active_rows_; }

  const InterfaceFields& interface() const { return iface_; }
  const EnergyBalance& energy() const { return energy_; }
  const VectorField& displacement() const { return u_; }
  const VectorField& velocity() const { return v_; }
  VectorField& displacement() { return u_; } // for verification set-ups
  VectorField& velocity() { return v_; }
  // Mark every row as possibly non-zero (after a test wrote initial fields by hand); with
  // the mesh damping on, also recomputes w = u + a v from them.
  void activate_all_rows();
  double damping_coefficient() const { return damping_a_; } // a [s]
  // Skip the quiet far field (rows and columns that hold exact zeros; on by default). Off,
  // every node is swept at every step: the same bits, slower (for tests).
  void set_skip_quiet(bool on) { skip_quiet_ = on; }
  // The columns of row j that may be non-zero after the last step (solver/fe/quiet_columns.hpp).
  ColumnRange active_columns(int j) const { return columns_[j]; }
  // Node updates the steps so far have made (the nodes they swept; bulk rows' columns).
  long long swept_node_updates() const { return swept_node_updates_; }

  double node_mass(int j) const; // lumped mass of a node of row j [kg/m]

private:
  // What one step of a block leaves behind until the block is summed up (in step order).
  struct LevelRecord {
    double time = 0; // t_n of the step
    bool compute_energy = false;
    InterfaceFields iface;                                       // the interface after the step
    EnergyBalance energy;                                        // the balance after the step
    std::vector<double> row_kinetic, row_strain, row_dissipated; // per row
    double work = 0;     // work of the load changes in the step
    long long swept = 0; // node updates made
  };
  // Row step r of a step (solver/fe/level_pipeline.hpp): v of row r from u of rows r-1, r,
  // r+1, then u of row r-1 from its new v (and that row's quiet-column range).
  void row_step(LevelRecord& level, int r, std::vector<double>& scratch);
  // The velocity part for the interface, the absorbing top and the damped rows.
  void velocity_row(LevelRecord& level, int j, ColumnRange cols, std::vector<double>& scratch);
  // A bulk row's velocity and the displacement of the row below, block of columns by block.
  void bulk_row_step(LevelRecord& level, int r, ColumnRange cols, std::vector<double>& scratch);
  // v of bulk row r (undamped) on columns [begin, begin + n); energy terms if kin, str.
  void bulk_velocity(int r, int begin, int n, double* kin, double* str);
  void finish_displacement_row(int j); // ghosts and quiet-column range of row j after its u
  // The columns of row j this step sweeps, from the ranges of rows j-1, j, j+1.
  ColumnRange sweep_columns(int j) const;
  void reserve_scratch(int members);
  void interface_row(LevelRecord& level);
  void absorbing_top_row(LevelRecord& level, const double* uxm, const double* uym);
  void damped_interior_row(LevelRecord& level, int j, const NodeStencil& s, ColumnRange cols,
                           std::vector<double>& scratch);
  // K w - K u (= a K v^{n-1/2}) of the row j into dx, dy, from the rows of u and w.
  void damping_force_row(const NodeStencil& s, int j, double* dx, double* dy) const;
  void update_displacement_row(int j); // advance_displacement on its columns, then finish
  void advance_displacement(int j, int begin, int end); // u += dt v (and w) on [begin, end)
  void update_damping_row(int j);                       // w = u + a v on row j, with its ghosts
  // Row j's kinetic and strain energy from its per-node terms, summed in node order.
  void store_row_energy(LevelRecord& level, int j, const double* kin, const double* str,
                        int count) const;

  SimulationParams params_;
  int nx_, ny_;
  double dx_, height_, dt_, stable_dt_;
  MeshStencils stencils_;
  SymmetricStencil interior_form_;  // the interior stencil in its symmetric form ...
  bool interior_symmetric_ = false; // ... if it has one (solver/fe/stencil.hpp)
  VectorField u_, v_;
  double damping_a_ = 0;          // a = zeta dx / c_s [s]; 0: undamped, w_ unused
  VectorField w_;                 // u + a v^{n-1/2}, with the damping on
  std::vector<double> kdx_, kdy_; // damping force row of the interface
  // ... and of the absorbing top: a row of its own, another thread may be on the interface.
  std::vector<double> kdx_top_, kdy_top_;
  std::vector<double> zero_row_;      // nx + 2 zeros, a neighbour for boundary rows
  std::vector<double> load1_, load2_; // interface load changes of this step [N/m]
  std::vector<double> kx0_, ky0_;     // K u on the interface row
  InterfaceNodeConstants node_;
  InterfaceParameters parameters_;      // tau0, sigma0 and friction values per interface node
  std::vector<FrictionState> friction_; // the friction state of each interface node
  InterfaceFields iface_;
  EnergyBalance energy_;
  std::vector<LevelRecord> levels_;                 // the steps of the last block
  std::vector<std::vector<double>> energy_scratch_; // per team member: 3 rows of energy terms
  long step_ = 0;
  int active_rows_ = 1; // rows >= active_rows_ hold exact zeros in u and v
  bool skip_quiet_ = true;
  std::vector<ColumnRange> columns_;      // per row: u and v are exact zeros outside
  std::vector<ColumnRange> next_columns_; // per row: the columns its current step sweeps
  long long swept_node_updates_ = 0;
};

} // namespace slipfront::fe
