#include "solver/fe/mesh_stepper.hpp"

#include "solver/fe/level_pipeline.hpp"
#include "solver/mesh_size.hpp"

#include <algorithm>

namespace slipfront::fe {

namespace {

ElasticBlock upper_block(const SimulationParams& params) {
  const MeshSize m = mesh_size(params);
  return ElasticBlock(params.material, m.nx, m.ny, m.dx, params.top, params.fe.mesh_damping,
                      m.layer_rows);
}

// The lower solid's block in its mirrored frame: the far row is the bottom.
std::optional<ElasticBlock> lower_block(const SimulationParams& params) {
  if (!params.lower.elastic()) return std::nullopt;
  const MeshSize m = lower_mesh_size(params);
  return ElasticBlock(params.lower.material, m.nx, m.ny, m.dx, params.lower.bottom,
                      params.fe.mesh_damping);
}

} // namespace

MeshStepper::MeshStepper(const SimulationParams& params)
    : params_(params), upper_(upper_block(params)), lower_(lower_block(params)) {
  // The free blocks bound every contact state (stick ties the pair, a constraint that cannot
  // raise the largest eigenvalue): the smaller of their stable steps (docs/physics.md).
  stable_dt_ = upper_.stable_dt();
  if (lower_) stable_dt_ = std::min(stable_dt_, lower_->stable_dt());
  dt_ = params.time.safety_factor * stable_dt_;
  upper_.set_time_step(dt_);
  if (lower_) lower_->set_time_step(dt_);
  const int nx = upper_.nx();
  const double dx = upper_.dx();
  load1_.assign(nx, 0.0);
  load2_.assign(nx, 0.0);
  node_ = {upper_.node_mass(0), upper_.node_mass(0), dt_, dx, StrengthLaw(params.friction)};
  parameters_ = interface_parameters(params, nx, dx);
  friction_ = resting_friction(parameters_, node_.law);
  iface_ = resting_interface(parameters_, node_.law);
}

void MeshStepper::reserve_scratch(int members) {
  if (int(energy_scratch_.size()) < members)
    energy_scratch_.resize(members, std::vector<double>(3 * upper_.nx()));
}

void MeshStepper::activate_all_rows() {
  upper_.activate_all_rows();
  if (lower_) lower_->activate_all_rows();
}

void MeshStepper::set_skip_quiet(bool on) {
  upper_.set_skip_quiet(on);
  if (lower_) lower_->set_skip_quiet(on);
}

void MeshStepper::step(ThreadTeam& team, bool compute_energy) {
  advance(team, std::vector<bool>{compute_energy});
}

void MeshStepper::advance(ThreadTeam& team, const std::vector<bool>& energy_steps) {
  const int count = int(energy_steps.size());
  if (count == 0) return;
  if (int(levels_.size()) < count) levels_.resize(count);
  for (int k = 0; k < count; ++k) {
    LevelRecord& level = levels_[k];
    level.time = double(step_ + k) * dt_;
    level.compute_energy = energy_steps[k];
    level.upper.reset(upper_.ny(), energy_steps[k]);
    if (lower_) level.lower.reset(lower_->ny(), energy_steps[k]);
    level.work = 0;
  }
  reserve_scratch(team.size());
  const int rows = lower_ ? std::max(upper_.ny(), lower_->ny()) : upper_.ny();
  run_level_pipeline(team, count, rows, [&](int k, int r, int member) {
    row_step(levels_[k], r, energy_scratch_[member]);
  });

  // Sum each step's per-row terms in row order (the upper block's rows, then the lower's), the
  // steps in order: the same result for any number of threads and steps per trip.
  for (int k = 0; k < count; ++k) {
    LevelRecord& level = levels_[k];
    double dissipated = 0, kinetic = 0, strain = 0;
    for (const BlockStepRecord* block : {&level.upper, lower_ ? &level.lower : nullptr}) {
      if (block == nullptr) continue;
      for (double d : block->row_dissipated)
        dissipated += d;
      if (!level.compute_energy) continue;
      for (double e : block->row_kinetic)
        kinetic += e;
      for (double e : block->row_strain)
        strain += e;
    }
    energy_.dissipated += dissipated;
    energy_.external_work += level.work;
    if (level.compute_energy) {
      energy_.kinetic = kinetic;
      energy_.strain = strain;
    }
    level.energy = energy_;
    swept_node_updates_ += level.upper.swept + (lower_ ? level.lower.swept : 0);
  }
  upper_.finish_trip();
  if (lower_) lower_->finish_trip();
  step_ += count;
}

void MeshStepper::row_step(LevelRecord& level, int r, std::vector<double>& scratch) {
  if (r == 0) {
    upper_.begin_interface_row(level.upper);
    if (lower_) lower_->begin_interface_row(level.lower);
    interface_row(level);
    level.iface = iface_;
    return;
  }
  upper_.row_step(level.upper, r, scratch);
  if (lower_) lower_->row_step(level.lower, r, scratch);
}

} // namespace slipfront::fe
