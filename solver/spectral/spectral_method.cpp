#include "solver/spectral/spectral_method.hpp"

#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"
#include "solver/interface/ill_posedness.hpp"
#include "solver/interface/nucleation.hpp"
#include "solver/mesh_size.hpp"
#include "solver/step_count.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace slipfront::spectral {

namespace {

constexpr double two_pi = 2.0 * std::numbers::pi;

} // namespace

double SpectralMethod::reference_shear_speed(const SimulationParams& p) {
  const double upper = p.material.s_wave_speed();
  return p.lower.elastic() ? std::max(upper, p.lower.material.s_wave_speed()) : upper;
}

double SpectralMethod::time_step(const SimulationParams& p) {
  const double dx = 1.0 / p.geometry.nodes_per_meter; // as mesh_size(p).dx, without the mesh
  return p.spectral.time_step_factor * dx / reference_shear_speed(p);
}

double SpectralMethod::side_step_factor(const SimulationParams& p, const Material& side) {
  // c_s dt / dx of this side: beta for the side that sets dt (exactly: the ratio is 1.0).
  return p.spectral.time_step_factor * (side.s_wave_speed() / reference_shear_speed(p));
}

double SpectralMethod::step_bound(const SimulationParams& p) {
  return steps_to_reach(p.time.duration, time_step(p)) + 1.0;
}

long SpectralMethod::max_steps(const SimulationParams& p) {
  return checked_step_count(step_bound(p));
}

double SpectralMethod::estimated_memory_bytes(const SimulationParams& p) {
  const int nx = mesh_size(p).nx, modes = nx / 2 + 1;
  const long steps = max_steps(p);
  double lags = 0, table = 0; // table: the kernel tables
  for (const Material* side : solids(p)) {
    for (int n = 1; n < modes; ++n)
      lags +=
          double(ModeMemory::memory_length(n, p.geometry.width, time_step(p), side->s_wave_speed(),
                                           p.spectral.memory_periods, steps));
    table += 6.0 * 8.0 * kernel_span(p, *side) / HalfSpaceKernels::table_step;
  }
  const double memory = 7.0 * 8.0 * lags; // 4 history + 3 weight doubles a lag
  // Nodal and modal vectors of each solid, and the interface's per-node parameters and
  // friction state.
  const double fields = 40.0 * 8.0 * nx * double(solids(p).size()) + 12.0 * 8.0 * nx;
  const double records = 4.0 * 8.0 * double(steps);   // probe records
  const double sample_buffer = 64.0 * 6.0 * 8.0 * nx; // a chunk of samples in the writer
  const double baseline = 16.0e6;                     // code, libraries, HDF5 caches
  return memory + fields + table + records + sample_buffer + baseline;
}

RunWork SpectralMethod::estimated_work(const SimulationParams& p, double until) {
  const int nx = mesh_size(p).nx, modes = nx / 2 + 1;
  RunWork work;
  work.dt = time_step(p);
  work.steps = steps_to_reach(until, work.dt);
  work.interface_steps = work.steps * nx;
  if (coefficient_law(p.friction).rate_dependent()) // a solve in the predictor and each corrector
    work.rate_solves = work.interface_steps * (1 + p.spectral.corrector_passes);
  const double n = work.steps;
  const long steps = max_steps(p);
  for (const Material* side : solids(p)) {
    // sum over the steps of min(step, L): the history fills, then stays L lags long.
    for (int k = 1; k < modes; ++k) {
      const double lags = double(ModeMemory::memory_length(
          k, p.geometry.width, work.dt, side->s_wave_speed(), p.spectral.memory_periods, steps));
      work.lag_steps += lags >= n ? n * (n + 1) / 2 : lags * (lags + 1) / 2 + (n - lags) * lags;
    }
    work.transform_steps += n * nx * std::log2(double(std::max(nx, 2)));
  }
  return work;
}

std::vector<const Material*> SpectralMethod::solids(const SimulationParams& p) {
  if (p.lower.elastic()) return {&p.material, &p.lower.material};
  return {&p.material};
}

double SpectralMethod::kernel_span(const SimulationParams& p) {
  return kernel_span(p, p.material);
}

double SpectralMethod::kernel_span(const SimulationParams& p, const Material& side) {
  // The last weight of mode n ends at (M_n + 1/2) |k_n| c_s dt <= 2 pi q + 3/2 pi beta, and
  // never beyond the run: (max_steps + 1/2) |k_max| c_s dt with |k_max| = pi / dx (beta the
  // side's c_s dt / dx).
  const double beta = side_step_factor(p, side);
  const double window = two_pi * p.spectral.memory_periods + 1.5 * std::numbers::pi * beta;
  const double run = (step_bound(p) + 1.5) * std::numbers::pi * beta;
  return std::min(window, run) + 0.5;
}

namespace {

HalfSpaceGrid grid_of(const SimulationParams& p, const Material& side, int threads) {
  HalfSpaceGrid g;
  g.nx = mesh_size(p).nx;
  g.width = p.geometry.width;
  g.dt = SpectralMethod::time_step(p);
  g.memory_periods = p.spectral.memory_periods;
  g.max_steps = SpectralMethod::max_steps(p);
  g.kernel_span = SpectralMethod::kernel_span(p, side);
  g.parts = threads;
  return g;
}

} // namespace

SpectralMethod::SpectralMethod(const SimulationParams& params, int threads)
    : params_(params), nx_(mesh_size(params).nx), dx_(mesh_size(params).dx), dt_(time_step(params)),
      team_(threads), upper_(params.material, grid_of(params, params.material, team_.size())) {
  node_ = {upper_.eta1() * dx_ * dt_, upper_.eta2() * dx_ * dt_, dt_, dx_,
           StrengthLaw(params.friction)};
  if (params.lower.elastic()) {
    const Material& below = params.lower.material;
    lower_ = std::make_unique<HalfSpace>(below, grid_of(params, below, team_.size()));
  }
  for (auto* v : {&load1_, &load2_, &slip_speed_})
    v->assign(nx_, 0.0);
  solved_.resize(nx_);
  parameters_ = interface_parameters(params, nx_, dx_);
  friction_ = resting_friction(parameters_, node_.law);
  iface_ = resting_interface(parameters_, node_.law);
}

MeshInfo SpectralMethod::mesh_info() const {
  // No bulk: one row of nodes, no height, and no closed-form stable step (docs/spectral-bi.md).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  return {nx_, 1, dx_, nan, nan, dt_, team_.size(), Method::spectral_bi};
}

std::vector<std::string> SpectralMethod::end_warnings(double /*simulated_time*/) const {
  std::vector<std::string> warnings;
  if (std::string ill_posed = bimaterial_coulomb_warning(params_); !ill_posed.empty())
    warnings.push_back(std::move(ill_posed));
  // Measured (tests/solver/interface_growth_test.cpp): 0.021 c_s/dx at beta = 0.4, 0.025-0.030
  // at 0.5; none at 0.3 and 0.25 on every n_d tried.
  const bool plain_coulomb = coefficient_law(params_.friction).constant() &&
                             !effective_regularization(params_.friction).filters();
  if (plain_coulomb && params_.spectral.time_step_factor >= 0.35) {
    char msg[300];
    std::snprintf(msg, sizeof msg,
                  "plain Coulomb friction with spectral_bi.time_step_factor = %.3g: the scheme "
                  "grows a mesh-scale mode of steady sliding (about 0.03 c_s/dx) that the "
                  "continuum does not have; a time_step_factor of 0.25 removes it "
                  "(docs/verification.md)",
                  params_.spectral.time_step_factor);
    warnings.push_back(msg);
  }
  return warnings;
}

double SpectralMethod::slip_rate(int i) const {
  const double upper = upper_.motion().v1[i];
  return lower_ ? upper - lower_->motion().v1[i] : upper;
}

double SpectralMethod::new_slip_rate(int i) const {
  const double upper = upper_.motion().v1_new[i];
  return lower_ ? upper - lower_->motion().v1_new[i] : upper;
}

void SpectralMethod::solve_nodes(const std::vector<double>& slip_speed) {
  const double t_half = (double(step_) + 0.5) * dt_;
  HalfSpace::Motion& up = upper_.motion();
  for (int i = 0; i < nx_; ++i) {
    const double x1 = iface_.x1[i];
    const double sigma1 = parameters_.shear_stress[i], sigma2 = parameters_.normal_stress[i];
    InterfaceTraction load;
    if (params_.extra_load) load = params_.extra_load(x1, t_half);
    load.t1 += nucleation_shear_traction(params_.nucleation, x1, t_half);
    load.t2 += nucleation_traction(params_.nucleation, sigma2, x1, t_half);
    load1_[i] = load.t1;
    load2_[i] = load.t2;
    // The upper solid without the interface force: -sigma_2j dx = L_j with
    // sigma_2j = sigma0_j + f_j - eta_j V_j  =>  V = (sigma0 + f + L/dx) / eta (loads in Pa).
    const InterfaceSide upper{node_.mass1, node_.mass2,
                              (sigma1 + upper_.f1()[i] + load.t1) / upper_.eta1(),
                              (sigma2 + upper_.f2()[i] + load.t2) / upper_.eta2()};
    InterfaceSide lower;
    double gap = up.d2[i];
    if (lower_) {
      // The lower solid in the true frame (its memory f' from its mirrored frame):
      // sigma_12 = sigma0_1 - f'_1 + eta_1 V_1, sigma_22 = sigma0_2 + f'_2 + eta_2 V_2, and
      // sigma_2j dx = -L_j without the interface force (docs/spectral-bi.md "Two half-spaces").
      const HalfSpace& below = *lower_;
      lower = {below.eta1() * dx_ * dt_, below.eta2() * dx_ * dt_,
               -(sigma1 - below.f1()[i] + load.t1) / below.eta1(),
               -(sigma2 + below.f2()[i] + load.t2) / below.eta2()};
      gap += below.motion().d2[i]; // u2(upper) - u2(lower) = D_2 + D'_2
    }
    const SplitNodeStep pair =
        resolve_split_node(node_, parameters_.friction[i], gap, upper, lower, !lower_,
                           slip_speed[i], friction_[i], iface_.pressure[i]);
    solved_[i] = pair.relative;
    up.v1_new[i] = pair.upper.v1;
    up.v2_new[i] = pair.upper.v2;
    if (lower_) { // back to the mirrored frame
      lower_->motion().v1_new[i] = pair.lower.v1;
      lower_->motion().v2_new[i] = -pair.lower.v2;
    }
  }
}

void SpectralMethod::step(bool /*compute_energy*/) {
  team_.run([&](int member, int) {
    upper_.sum_history(member);
    if (lower_) lower_->sum_history(member);
  });
  upper_.known_memory_term();
  if (lower_) lower_->known_memory_term();

  // Predictor: this interval's memory term with V^{n-1/2}; the strength update with the
  // slip speed of the last interval. Corrector: with the solved V^{n+1/2}, and the mean slip
  // speed over [t_{n-1/2}, t_{n+1/2}]. Slip speeds are those of the relative motion.
  // Before the first step the medium is at rest, but a law of the slip rate may have the
  // interface slide already (rate-and-state's initial slip rate): the last interval's slip
  // speed is then that rate.
  std::vector<double>& slip_speed = slip_speed_;
  auto last_speed = [&](int i) {
    const double at_rest =
        step_ == 0 ? node_.law.coefficient().initial_slip_rate(parameters_.friction[i]) : 0.0;
    return std::max(std::abs(slip_rate(i)), at_rest);
  };
  for (int i = 0; i < nx_; ++i)
    slip_speed[i] = last_speed(i);
  upper_.predict();
  if (lower_) lower_->predict();
  solve_nodes(slip_speed);
  for (int pass = 1; pass <= params_.spectral.corrector_passes; ++pass) {
    for (int i = 0; i < nx_; ++i)
      slip_speed[i] = step_ == 0 ? 0.5 * (last_speed(i) + std::abs(new_slip_rate(i)))
                                 : std::abs(0.5 * (slip_rate(i) + new_slip_rate(i)));
    upper_.correct();
    if (lower_) lower_->correct();
    solve_nodes(slip_speed);
  }
  record_interface();
  upper_.finish_step();
  if (lower_) lower_->finish_step();
  ++step_;
}

void SpectralMethod::record_interface() {
  // The interface after step n (relative motion: upper minus lower), and the energy over the
  // step (V constant over it).
  const HalfSpace::Motion& up = upper_.motion();
  // The initial reaction C0_i = dx (-tau0_i, |sigma0_i|) of node i.
  auto c0_1 = [&](int i) { return -parameters_.shear_stress[i] * dx_; };
  auto c0_2 = [&](int i) { return std::abs(parameters_.normal_stress[i]) * dx_; };
  const std::vector<double>&f1 = upper_.f1(), &f2 = upper_.f2();
  const double eta1 = upper_.eta1(), eta2 = upper_.eta2();
  double work = 0, dissipated = 0, delivered = 0;
  for (int i = 0; i < nx_; ++i) {
    const InterfaceNodeStep& r = solved_[i];
    const double v1 = up.v1_new[i], v2 = up.v2_new[i];
    iface_.velocity[i] = 0.5 * (up.v1[i] + v1);
    iface_.half_velocity[i] = v1;
    iface_.slip[i] = up.d1[i];
    iface_.opening[i] = up.d2[i];
    iface_.shear_traction[i] = -r.contact_force1 / dx_;
    iface_.pressure[i] = r.pressure;
    iface_.strength[i] = r.strength;
    iface_.state[i] = std::int8_t(r.state);
    friction_[i] = r.friction;
    // Work of the load changes: the interface loads and the release of the initial reaction.
    work += dt_ * ((load1_[i] * dx_ - c0_1(i)) * v1 + (load2_[i] * dx_ - c0_2(i)) * v2);
    dissipated -= dt_ * (r.contact_force1 * v1 + r.contact_force2 * v2);
    // Energy into the half-space: -(sigma - sigma0) . V = (eta V - f) . V per unit length.
    delivered += dt_ * dx_ * ((eta1 * v1 - f1[i]) * v1 + (eta2 * v2 - f2[i]) * v2);
  }
  if (lower_) { // the lower side's part, and the relative motion replaces the upper's
    const HalfSpace::Motion& lo = lower_->motion();
    const std::vector<double>&g1 = lower_->f1(), &g2 = lower_->f2();
    const double e1 = lower_->eta1(), e2 = lower_->eta2();
    work = dissipated = 0;
    double into_lower = 0;
    for (int i = 0; i < nx_; ++i) {
      const InterfaceNodeStep& r = solved_[i];
      const double v1 = up.v1_new[i] - lo.v1_new[i], v2 = up.v2_new[i] + lo.v2_new[i];
      iface_.velocity[i] = 0.5 * (slip_rate(i) + v1);
      iface_.half_velocity[i] = v1;
      iface_.slip[i] = up.d1[i] - lo.d1[i];
      iface_.opening[i] = up.d2[i] + lo.d2[i];
      // The loads act as +L on the upper side and -L on the lower, the interface force as +C
      // and -C, the initial reaction as +C0 and -C0: each does its work on the relative motion.
      work += dt_ * ((load1_[i] * dx_ - c0_1(i)) * v1 + (load2_[i] * dx_ - c0_2(i)) * v2);
      dissipated -= dt_ * (r.contact_force1 * v1 + r.contact_force2 * v2);
      // In the mirrored frame (where lo and g live) the lower side is an upper half-space.
      const double w1 = lo.v1_new[i], w2 = lo.v2_new[i];
      into_lower += dt_ * dx_ * ((e1 * w1 - g1[i]) * w1 + (e2 * w2 - g2[i]) * w2);
    }
    delivered += into_lower;
    energy_.lower_solid += into_lower;
  }
  energy_.external_work += work;
  energy_.dissipated += dissipated;
  energy_.kinetic = 0.0;
  energy_.strain += delivered;
}

} // namespace slipfront::spectral
