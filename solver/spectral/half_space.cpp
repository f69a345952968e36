#include "solver/spectral/half_space.hpp"

#include <algorithm>
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

HalfSpace::HalfSpace(const Material& mat, const HalfSpaceGrid& grid)
    : nx_(grid.nx), modes_(grid.nx / 2 + 1), dt_(grid.dt), eta1_(mat.density * mat.s_wave_speed()),
      eta2_(mat.density * mat.p_wave_speed()),
      kernels_(mat.s_wave_speed() / mat.p_wave_speed(), grid.kernel_span), fft_(grid.nx) {
  memory_ = std::make_unique<ModeMemory>(modes_, grid.width, dt_, mat.s_wave_speed(), eta1_,
                                         grid.memory_periods, grid.max_steps, kernels_);
  mu_k_.resize(modes_);
  for (int n = 0; n < modes_; ++n)
    mu_k_[n] = mat.shear_modulus() * two_pi * n / grid.width;
  for (auto* v : {&d1_hat_, &d2_hat_, &v1_hat_, &v2_hat_, &v1_hat_new_, &v2_hat_new_, &f1_known_,
                  &f2_known_, &f1_hat_, &f2_hat_})
    v->assign(modes_, complex(0.0, 0.0));
  sums_.resize(modes_);
  for (auto* v : {&f1_, &f2_, &motion_.d1, &motion_.d2, &motion_.v1, &motion_.v2, &motion_.v1_new,
                  &motion_.v2_new})
    v->assign(nx_, 0.0);
  split_ = split_modes(*memory_, grid.max_steps, grid.parts);
}

void HalfSpace::sum_history(int member) {
  const int first = split_[member], last = split_[member + 1];
  if (first < last) memory_->history_sums(first, last, sums_.data() + first);
}

void HalfSpace::known_memory_term() {
  // f_hat_1 = mu|k| K11(0) D1 - sum W11 V1 + i (mu|k| K12(0) D2 - sum W12 V2)
  // f_hat_2 = mu|k| K22(0) D2 - sum W22 V2 - i (mu|k| K12(0) D1 - sum W12 V1)
  // (the weights carry mu |k|). The Nyquist mode of a real field has no coupling.
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

void HalfSpace::add_current_interval(const std::vector<complex>& v1,
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

void HalfSpace::forward_new_velocity() {
  fft_.forward(motion_.v1_new.data(), v1_hat_new_.data());
  fft_.forward(motion_.v2_new.data(), v2_hat_new_.data());
}

void HalfSpace::predict() {
  add_current_interval(v1_hat_, v2_hat_);
}

void HalfSpace::correct() {
  forward_new_velocity();
  add_current_interval(v1_hat_new_, v2_hat_new_);
}

void HalfSpace::finish_step() {
  forward_new_velocity();
  memory_->push(v1_hat_new_.data(), v2_hat_new_.data());
  for (int n = 0; n < modes_; ++n) {
    d1_hat_[n] += dt_ * v1_hat_new_[n];
    d2_hat_[n] += dt_ * v2_hat_new_[n];
  }
  v1_hat_.swap(v1_hat_new_);
  v2_hat_.swap(v2_hat_new_);
  for (int i = 0; i < nx_; ++i) {
    motion_.d1[i] += dt_ * motion_.v1_new[i];
    motion_.d2[i] += dt_ * motion_.v2_new[i];
  }
  motion_.v1.swap(motion_.v1_new);
  motion_.v2.swap(motion_.v2_new);
}

} // namespace slipfront::spectral
