// The FE method's mesh stepper: the elastic block of the upper solid (solver/fe/elastic_block.hpp)
// on the rigid plane or on a second elastic block, the lower solid (params.lower); the
// interface between them; and one explicit central-difference step (the RuptureMethod around
// it: solver/fe/finite_element_method.hpp).
//
// Perturbation formulation: u, v are the displacement and velocity on top of the uniform,
// stuck, pre-stressed initial state. The far boundaries keep their remote traction, so they
// are free for the perturbation (or absorbing). At an interface node the lower side (the plane
// or the lower solid's node) exerts the total force C = (C1, C2) on the upper solid's node,
// and the upper node -C on the lower node; in the initial state C0 = dx (-tau1_0, |tau2_0|),
// so the perturbation of the upper block sees C - C0 and that of the lower block -(C - C0)
// (the release of the pre-stress when the pair slips or opens).
//
// Two solids (docs/physics.md "Two solids"): the lower block is an ElasticBlock in its mirrored
// frame y' = -x2. Level r of a step does row r of each block (a row beyond a block's height is
// nothing); level 0 is the interface, where the pair of nodes i is solved by the split-node law
// (solver/interface/split_node.hpp) in the true frame.
//
// Central differences (explicit Newmark beta = 0, gamma = 1/2) in leapfrog form:
//   v^{n+1/2} = v^{n-1/2} + dt M^-1 (F^n - K u^n),   u^{n+1} = u^n + dt v^{n+1/2},
// with M lumped. The stored velocity is that of the last half step.
//
// Several steps can be taken in one trip over the rows (advance): each step two rows behind
// the one before (solver/fe/level_pipeline.hpp), with the same bits as stepping one at a time.
//
// Optional mesh-scale damping (params.fe.mesh_damping = zeta > 0, docs/physics.md): a
// stiffness-proportional (Kelvin-Voigt) force -a K v with a = zeta dx / c_s, taken at the
// last half step's velocity v^{n-1/2} so that the step stays explicit:
//   v^{n+1/2} = v^{n-1/2} + dt M^-1 (F^n - K (u^n + a v^{n-1/2})).
// w = u + a v is kept beside u (advanced with it, row by row), so K w comes from the same
// stencil pass as K u. The stable step shrinks to sqrt(a^2 + dt0^2) - a
// (damped_stable_time_step); the damping's work goes into the dissipated energy.
#pragma once

#include "solver/fe/elastic_block.hpp"
#include "solver/interface/interface_fields.hpp"
#include "solver/interface/interface_law.hpp"
#include "solver/params.hpp"
#include "solver/thread_team.hpp"

#include <optional>
#include <vector>

namespace slipfront::fe {

class MeshStepper {
public:
  explicit MeshStepper(const SimulationParams& params);

  // Advance from t_n to t_{n+1}. With compute_energy the kinetic and strain terms of the
  // energy balance are evaluated in the same sweep (else they keep their last value).
  void step(ThreadTeam& team, bool compute_energy);
  // Advance energy_steps.size() steps in one trip over the rows (temporal blocking over the
  // team's threads); energy_steps[k]: evaluate the energy terms in step k of the trip. The
  // same bits as that many step() calls. After it, interface_after(k) and energy_after(k) are
  // those after step k of the trip; interface() and energy() those after the last.
  void advance(ThreadTeam& team, const std::vector<bool>& energy_steps);
  const InterfaceFields& interface_after(int k) const { return levels_[k].iface; }
  const EnergyBalance& energy_after(int k) const { return levels_[k].energy; }

  int nx() const { return upper_.nx(); }
  int ny() const { return upper_.ny(); }
  double dx() const { return upper_.dx(); }
  double height() const { return upper_.height(); }
  double dt() const { return dt_; }
  double stable_dt() const { return stable_dt_; }
  long steps_done() const { return step_; }
  double time() const { return step_ * dt_; } // t_n of the state (u^n)
  int active_rows() const { return upper_.active_rows(); }

  const InterfaceFields& interface() const { return iface_; }
  const EnergyBalance& energy() const { return energy_; }
  // The upper solid's block (x2 >= 0), and the lower solid's in its mirrored frame (x2 <= 0;
  // null on the rigid plane).
  const ElasticBlock& upper() const { return upper_; }
  const ElasticBlock* lower() const { return lower_ ? &*lower_ : nullptr; }
  ElasticBlock* lower() { return lower_ ? &*lower_ : nullptr; } // for verification set-ups
  const VectorField& displacement() const { return upper_.displacement(); }
  const VectorField& velocity() const { return upper_.velocity(); }
  VectorField& displacement() { return upper_.displacement(); } // for verification set-ups
  VectorField& velocity() { return upper_.velocity(); }
  // Mark every row of both blocks as possibly non-zero (after a test wrote initial fields by
  // hand); with the mesh damping on, also recomputes w = u + a v from them.
  void activate_all_rows();
  double damping_coefficient() const { return upper_.damping_coefficient(); } // a [s]
  // Skip the quiet far field (rows and columns that hold exact zeros; on by default). Off,
  // every node is swept at every step: the same bits, slower (for tests).
  void set_skip_quiet(bool on);
  // The columns of row j that may be non-zero after the last step (solver/fe/quiet_columns.hpp).
  ColumnRange active_columns(int j) const { return upper_.active_columns(j); }
  // Node updates the steps so far have made (the nodes they swept; bulk rows' columns).
  long long swept_node_updates() const { return swept_node_updates_; }

  double node_mass(int j) const { return upper_.node_mass(j); } // [kg/m], upper block

private:
  // What one step of a trip leaves behind until the trip is summed up (in step order).
  struct LevelRecord {
    double time = 0; // t_n of the step
    bool compute_energy = false;
    InterfaceFields iface; // the interface after the step
    EnergyBalance energy;  // the balance after the step
    BlockStepRecord upper; // per-row energy terms and node updates of the upper block
    BlockStepRecord lower; // ... and of the lower block (with an elastic lower solid)
    double work = 0;       // work of the load changes in the step
  };
  // Row step r of a step (solver/fe/level_pipeline.hpp): row 0 is the interface.
  void row_step(LevelRecord& level, int r, std::vector<double>& scratch);
  // The interface law on row 0 (solver/fe/interface_row.cpp), after the block's K u of it.
  void interface_row(LevelRecord& level);
  void reserve_scratch(int members);

  SimulationParams params_;
  ElasticBlock upper_;
  std::optional<ElasticBlock> lower_; // the lower solid's block, mirrored; none: the rigid plane
  double dt_, stable_dt_;
  std::vector<double> load1_, load2_; // interface load changes of this step [N/m]
  InterfaceNodeConstants node_;
  InterfaceFields iface_;
  EnergyBalance energy_;
  std::vector<LevelRecord> levels_;                 // the steps of the last trip
  std::vector<std::vector<double>> energy_scratch_; // per team member: 3 rows of energy terms
  long step_ = 0;
  long long swept_node_updates_ = 0;
};

} // namespace slipfront::fe
