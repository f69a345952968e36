// The elastodynamic memory of the half-space, mode by mode (docs/spectral-bi.md).
//
// For each Fourier mode k_n = 2 pi n / w of the interface it keeps the velocity history
// V_hat_j of the last M_n steps (M_n = q mode periods 2 pi / (|k_n| c_s), at most the whole
// run) and the convolution weights
//     W_m = int g(|k| c_s t') dt' over t' in [(m - 1/2) dt, (m + 1/2) dt]   (m >= 1),
//     W_0 = int over [0, dt/2],
// so that at t_{n+1/2}, with V piecewise constant over the steps,
//     (g * V)(t_{n+1/2}) = W_0 V^{n+1/2} + sum_{m >= 1} W_m V^{n+1/2-m}.
// The truncation drops the lags beyond M_n: in the velocity form this keeps the static
// response exact and loses only the tail int_{t_w}^inf g V of a kernel decaying as T^-3/2.
#pragma once

#include "solver/spectral/half_space_kernels.hpp"

#include <array>
#include <complex>
#include <cstddef>
#include <vector>

namespace slipfront::spectral {

// Sums over the stored history of one mode (the parts of f_hat that are already known).
struct ModeHistorySums {
  std::complex<double> w11_v1, w22_v2, w12_v2, w12_v1;
};

class ModeMemory {
public:
  // modes: n = 0 .. N/2; k_n = 2 pi n / width. Weights are scaled by rho c_s (= mu / c_s),
  // so that mu |k| W_m = rho c_s int g dT.
  ModeMemory(int modes, double width, double dt, double shear_speed, double impedance_s,
             double memory_periods, long max_steps, const HalfSpaceKernels& kernels);

  // M_n: the lags mode n keeps (0 for the uniform mode n = 0).
  static long memory_length(int n, double width, double dt, double shear_speed,
                            double memory_periods, long max_steps);

  int modes() const { return int(length_.size()); }
  long length(int n) const { return length_[n]; } // M_n (0 for the uniform mode)
  std::size_t stored_values() const { return 4 * offset_.back(); }

  // The weights of the current interval (m = 0), scaled like the others.
  const KernelValues& current_weights(int n) const { return w0_[n]; }

  // Sums over lags 1 .. min(M_n, pushed) for the modes [first, last).
  void history_sums(int first, int last, ModeHistorySums* out) const;

  // Consecutive lags of one mode: their weights, and the history at the same lags.
  struct LagSpan {
    const double *w11, *w22, *w12;
    const double *v1r, *v1i, *v2r, *v2i;
  };

  // Store the velocities of the step just finished as lag 1 of the next step.
  void push(const std::complex<double>* v1, const std::complex<double>* v2);

private:
  // One array per component (structure of arrays), so that the sums over the lags run in
  // SIMD lanes; mode n occupies [offset_[n], offset_[n + 1]) of each.
  enum History { v1_re, v1_im, v2_re, v2_im };
  enum Weight { w11, w22, w12 };

  LagSpan span(int n, long first_lag, long position) const;

  std::vector<long> length_;                   // M_n
  std::vector<std::size_t> offset_;            // start of mode n in every component array
  std::vector<long> head_;                     // position of lag 1 in the ring of mode n
  std::array<std::vector<double>, 4> history_; // V1, V2 per lag, newest first (ring)
  std::array<std::vector<double>, 3> weights_; // W11, W22, W12 per lag m = 1 .. M_n
  std::vector<KernelValues> w0_;               // m = 0 (g fields only)
  long pushed_ = 0;
};

} // namespace slipfront::spectral
