#include "solver/spectral/spectral_method.hpp"

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

// Contiguous mode ranges [split[m], split[m + 1]) of about equal convolution work.
std::vector<int> split_modes(const ModeMemory& memory, long steps, int parts) {
  std::vector<double> cumulative(memory.modes() + 1, 0.0);
  for (int n = 0; n < memory.modes(); ++n)
    cumulative[n + 1] = cumulative[n] + double(std::min(memory.length(n), steps)) + 1.0;
  std::vector<int> split(parts + 1, memory.modes());
  split[0] = 0;
  for (int m = 1; m < parts; ++m) {
    const double target = cumulative.back() * m / parts;
    split[m] =
        int(std::lower_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin());
    split[m] = std::clamp(split[m], split[m - 1], memory.modes());
  }
  return split;
}

} // namespace

double SpectralMethod::time_step(const SimulationParams& p) {
  const double dx = 1.0 / p.geometry.nodes_per_meter; // as mesh_size(p).dx, without the mesh
  return p.spectral.time_step_factor * dx / p.material.s_wave_speed();
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
  double lags = 0;
  for (int n = 1; n < modes; ++n)
    lags += double(ModeMemory::memory_length(n, p.geometry.width, time_step(p),
                                             p.material.s_wave_speed(), p.spectral.memory_periods,
                                             steps));
  const double memory = 7.0 * 8.0 * lags; // 4 history + 3 weight doubles a lag
  const double fields = 52.0 * 8.0 * nx;  // nodal and modal vectors, per-node parameters
  const double table = 6.0 * 8.0 * kernel_span(p) / HalfSpaceKernels::table_step;
  const double records = 4.0 * 8.0 * double(steps);   // probe records
  const double sample_buffer = 64.0 * 6.0 * 8.0 * nx; // a chunk of samples in the writer
  const double baseline = 16.0e6;                     // code, libraries, HDF5 caches
  return memory + fields + table + records + sample_buffer + baseline;
}

double SpectralMethod::kernel_span(const SimulationParams& p) {
  // The last weight of mode n ends at (M_n + 1/2) |k_n| c_s dt <= 2 pi q + 3/2 pi beta, and
  // never beyond the run: (max_steps + 1/2) |k_max| c_s dt with |k_max| = pi / dx.
  const double beta = p.spectral.time_step_factor;
  const double window = two_pi * p.spectral.memory_periods + 1.5 * std::numbers::pi * beta;
  const double run = (step_bound(p) + 1.5) * std::numbers::pi * beta;
  return std::min(window, run) + 0.5;
}

SpectralMethod::SpectralMethod(const SimulationParams& params, int threads)
    : params_(params), nx_(mesh_size(params).nx), modes_(nx_ / 2 + 1), dx_(mesh_size(params).dx),
      dt_(time_step(params)), eta1_(params.material.density * params.material.s_wave_speed()),
      eta2_(params.material.density * params.material.p_wave_speed()),
      kernels_(params.material.s_wave_speed() / params.material.p_wave_speed(),
               kernel_span(params)),
      fft_(nx_), team_(threads) {
  const Material& mat = params.material;
  memory_ =
      std::make_unique<ModeMemory>(modes_, params.geometry.width, dt_, mat.s_wave_speed(), eta1_,
                                   params.spectral.memory_periods, max_steps(params), kernels_);
  node_ = {eta1_ * dx_ * dt_, eta2_ * dx_ * dt_, dt_, dx_, StrengthLaw(params.friction)};

  mu_k_.resize(modes_);
  for (int n = 0; n < modes_; ++n)
    mu_k_[n] = mat.shear_modulus() * two_pi * n / params.geometry.width;
  for (auto* v : {&d1_hat_, &d2_hat_, &v1_hat_, &v2_hat_, &v1_hat_new_, &v2_hat_new_, &f1_known_,
                  &f2_known_, &f1_hat_, &f2_hat_})
    v->assign(modes_, complex(0.0, 0.0));
  sums_.resize(modes_);
  for (auto* v :
       {&f1_, &f2_, &d1_, &d2_, &v1_, &v2_, &v1_new_, &v2_new_, &load1_, &load2_, &slip_speed_})
    v->assign(nx_, 0.0);
  solved_.resize(nx_);
  team_split_ = split_modes(*memory_, max_steps(params), team_.size());

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
  // Measured (tests/solver/interface_growth_test.cpp): 0.021 c_s/dx at beta = 0.4, 0.025-0.030
  // at 0.5; none at 0.3 and 0.25 on every n_d tried.
  if (params_.friction.law != FrictionLaw::coulomb || params_.spectral.time_step_factor < 0.35)
    return {};
  char msg[300];
  std::snprintf(msg, sizeof msg,
                "plain Coulomb friction with spectral_bi.time_step_factor = %.3g: the scheme grows "
                "a mesh-scale mode of steady sliding (about 0.03 c_s/dx) that the continuum does "
                "not have; a time_step_factor of 0.25 removes it (docs/verification.md)",
                params_.spectral.time_step_factor);
  return {msg};
}

void SpectralMethod::known_memory_term() {
  // f_hat_1 = mu|k| K11(0) D1 - sum W11 V1 + i (mu|k| K12(0) D2 - sum W12 V2)
  // f_hat_2 = mu|k| K22(0) D2 - sum W22 V2 - i (mu|k| K12(0) D1 - sum W12 V1)
  // (the weights carry mu |k|). The Nyquist mode of a real field has no coupling.
  team_.run([&](int member, int) {
    const int first = team_split_[member], last = team_split_[member + 1];
    if (first < last) memory_->history_sums(first, last, sums_.data() + first);
  });
  const complex i(0.0, 1.0);
  const double k11 = kernels_.static11(), k22 = kernels_.static22(), k12 = kernels_.static12();
  f1_known_[0] = f2_known_[0] = 0.0; // a uniform motion radiates plane waves: no memory
  for (int n = 1; n < modes_; ++n) {
    const ModeHistorySums& s = sums_[n];
    const bool coupled = 2 * n != nx_;
    const complex c1 = coupled ? i * (mu_k_[n] * k12 * d2_hat_[n] - s.w12_v2) : 0.0;
    const complex c2 = coupled ? i * (mu_k_[n] * k12 * d1_hat_[n] - s.w12_v1) : 0.0;
    f1_known_[n] = mu_k_[n] * k11 * d1_hat_[n] - s.w11_v1 + c1;
    f2_known_[n] = mu_k_[n] * k22 * d2_hat_[n] - s.w22_v2 - c2;
  }
}

void SpectralMethod::add_current_interval(const std::vector<complex>& v1,
                                          const std::vector<complex>& v2) {
  // D^{n+1/2} = D^n + dt/2 V and the lag-0 weight, both acting on this interval's V.
  const complex i(0.0, 1.0);
  const double half = 0.5 * dt_;
  f1_hat_[0] = f2_hat_[0] = 0.0;
  for (int n = 1; n < modes_; ++n) {
    const KernelValues& w0 = memory_->current_weights(n);
    const double a11 = mu_k_[n] * kernels_.static11() * half - w0.g11;
    const double a22 = mu_k_[n] * kernels_.static22() * half - w0.g22;
    const double a12 = 2 * n != nx_ ? mu_k_[n] * kernels_.static12() * half - w0.g12 : 0.0;
    f1_hat_[n] = f1_known_[n] + a11 * v1[n] + i * a12 * v2[n];
    f2_hat_[n] = f2_known_[n] + a22 * v2[n] - i * a12 * v1[n];
  }
  fft_.inverse(f1_hat_.data(), f1_.data());
  fft_.inverse(f2_hat_.data(), f2_.data());
}

void SpectralMethod::solve_nodes(const std::vector<double>& slip_speed) {
  const double t_half = (double(step_) + 0.5) * dt_;
  for (int i = 0; i < nx_; ++i) {
    const double x1 = iface_.x1[i];
    const double sigma1 = parameters_.shear_stress[i], sigma2 = parameters_.normal_stress[i];
    InterfaceTraction load;
    if (params_.extra_load) load = params_.extra_load(x1, t_half);
    load.t2 += nucleation_traction(params_.nucleation, sigma2, x1, t_half);
    load1_[i] = load.t1;
    load2_[i] = load.t2;
    // The velocity without the plane's force: -sigma_2j = L_j  =>  V = (sigma0 + f + L)/eta.
    const double v1_free = (sigma1 + f1_[i] + load.t1) / eta1_;
    const double v2_free = (sigma2 + f2_[i] + load.t2) / eta2_;
    solved_[i] = resolve_interface_node(node_, parameters_.friction[i], d2_[i], v1_free, v2_free,
                                        slip_speed[i], friction_[i], iface_.pressure[i]);
    v1_new_[i] = solved_[i].v1;
    v2_new_[i] = solved_[i].v2;
  }
}

void SpectralMethod::step(bool /*compute_energy*/) {
  known_memory_term();

  // Predictor: this interval's memory term with V^{n-1/2}; the strength update with the
  // slip speed of the last interval. Corrector: with the solved V^{n+1/2}, and the mean slip
  // speed over [t_{n-1/2}, t_{n+1/2}].
  std::vector<double>& slip_speed = slip_speed_;
  std::vector<complex>&v1_hat = v1_hat_new_, &v2_hat = v2_hat_new_;
  for (int i = 0; i < nx_; ++i)
    slip_speed[i] = std::abs(v1_[i]);
  add_current_interval(v1_hat_, v2_hat_);
  solve_nodes(slip_speed);
  for (int pass = 1; pass <= params_.spectral.corrector_passes; ++pass) {
    fft_.forward(v1_new_.data(), v1_hat.data());
    fft_.forward(v2_new_.data(), v2_hat.data());
    for (int i = 0; i < nx_; ++i)
      slip_speed[i] = std::abs(0.5 * (v1_[i] + v1_new_[i]));
    add_current_interval(v1_hat, v2_hat);
    solve_nodes(slip_speed);
  }
  fft_.forward(v1_new_.data(), v1_hat.data());
  fft_.forward(v2_new_.data(), v2_hat.data());

  // The interface after step n, and the energy over the step (V constant over it).
  double work = 0, dissipated = 0, delivered = 0;
  for (int i = 0; i < nx_; ++i) {
    const InterfaceNodeStep& r = solved_[i];
    const double c0_1 = -parameters_.shear_stress[i] * dx_; // the initial reaction C0
    const double c0_2 = std::abs(parameters_.normal_stress[i]) * dx_;
    const double v1 = v1_new_[i], v2 = v2_new_[i];
    iface_.velocity[i] = 0.5 * (v1_[i] + v1);
    iface_.half_velocity[i] = v1;
    iface_.slip[i] = d1_[i];
    iface_.opening[i] = d2_[i];
    iface_.shear_traction[i] = -r.contact_force1 / dx_;
    iface_.pressure[i] = r.pressure;
    iface_.strength[i] = r.strength;
    iface_.state[i] = std::int8_t(r.state);
    friction_[i] = r.friction;
    // Work of the load changes: the interface loads and the release of the initial reaction.
    work += dt_ * ((load1_[i] * dx_ - c0_1) * v1 + (load2_[i] * dx_ - c0_2) * v2);
    dissipated -= dt_ * (r.contact_force1 * v1 + r.contact_force2 * v2);
    // Energy into the half-space: -(sigma - sigma0) . V = (eta V - f) . V per unit length.
    delivered += dt_ * dx_ * ((eta1_ * v1 - f1_[i]) * v1 + (eta2_ * v2 - f2_[i]) * v2);
  }
  energy_.external_work += work;
  energy_.dissipated += dissipated;
  energy_.kinetic = 0.0;
  energy_.strain += delivered;

  memory_->push(v1_hat.data(), v2_hat.data());
  for (int n = 0; n < modes_; ++n) {
    d1_hat_[n] += dt_ * v1_hat[n];
    d2_hat_[n] += dt_ * v2_hat[n];
  }
  v1_hat_.swap(v1_hat);
  v2_hat_.swap(v2_hat);
  for (int i = 0; i < nx_; ++i) {
    d1_[i] += dt_ * v1_new_[i];
    d2_[i] += dt_ * v2_new_[i];
  }
  v1_.swap(v1_new_);
  v2_.swap(v2_new_);
  ++step_;
}

} // namespace slipfront::spectral
