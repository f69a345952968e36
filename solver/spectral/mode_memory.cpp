#include "solver/spectral/mode_memory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slipfront::spectral {

namespace {

// The 8 real sums over `count` lags of the weights times the history, added to acc:
//   acc = {W11 V1, W22 V2, W12 V2, W12 V1} (re, im each).
// `omp simd` lets the compiler split each sum into SIMD lanes (a different but fixed order
// of the additions: results are reproducible, not bit-equal to a sequential sum).
inline void accumulate(const ModeMemory::LagSpan& s, long count, double* acc) {
  const double* __restrict w11 = s.w11, * __restrict w22 = s.w22, * __restrict w12 = s.w12;
  const double* __restrict v1r = s.v1r, * __restrict v1i = s.v1i;
  const double* __restrict v2r = s.v2r, * __restrict v2i = s.v2i;
  double a0 = 0, a1 = 0, a2 = 0, a3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
#pragma omp simd reduction(+ : a0, a1, a2, a3, b0, b1, b2, b3)
  for (long m = 0; m < count; ++m) {
    a0 += w11[m] * v1r[m];
    a1 += w11[m] * v1i[m];
    a2 += w22[m] * v2r[m];
    a3 += w22[m] * v2i[m];
    b0 += w12[m] * v2r[m];
    b1 += w12[m] * v2i[m];
    b2 += w12[m] * v1r[m];
    b3 += w12[m] * v1i[m];
  }
  acc[0] += a0, acc[1] += a1, acc[2] += a2, acc[3] += a3;
  acc[4] += b0, acc[5] += b1, acc[6] += b2, acc[7] += b3;
}

} // namespace

long ModeMemory::memory_length(int n, double width, double dt, double shear_speed,
                               double memory_periods, long max_steps) {
  if (n == 0) return 0;
  const double k = 2.0 * std::numbers::pi * n / width;
  const double window = memory_periods * 2.0 * std::numbers::pi / (k * shear_speed); // [s]
  // Clamped in double: window / dt may be beyond every integer type (a tiny dt).
  const double lags = std::ceil(window / dt);
  const double most = double(std::max(1L, max_steps));
  return lags >= 1.0 ? long(std::min(lags, most)) : 1L;
}

ModeMemory::ModeMemory(int modes, double width, double dt, double shear_speed, double impedance_s,
                       double memory_periods, long max_steps, const HalfSpaceKernels& kernels)
    : length_(modes, 0), offset_(modes + 1, 0), head_(modes, 0), w0_(modes) {
  const double two_pi = 2.0 * std::numbers::pi;
  for (int n = 1; n < modes; ++n) {
    length_[n] = memory_length(n, width, dt, shear_speed, memory_periods, max_steps);
    offset_[n + 1] = offset_[n] + std::size_t(length_[n]);
  }
  for (auto& component : history_)
    component.assign(offset_[modes], 0.0);
  for (auto& component : weights_)
    component.assign(offset_[modes], 0.0);

  for (int n = 1; n < modes; ++n) {
    const double scale = shear_speed * two_pi * n / width * dt; // T per step
    // mu |k| W = (mu / c_s) int g dT = impedance_s * int g dT.
    const KernelValues first = kernels.integral(0.0, 0.5 * scale);
    w0_[n] = {impedance_s * first.g11, impedance_s * first.g22, impedance_s * first.g12, 0, 0, 0};
    for (long m = 1; m <= length_[n]; ++m) {
      const KernelValues v = kernels.integral((m - 0.5) * scale, (m + 0.5) * scale);
      const std::size_t at = offset_[n] + std::size_t(m - 1);
      weights_[w11][at] = impedance_s * v.g11;
      weights_[w22][at] = impedance_s * v.g22;
      weights_[w12][at] = impedance_s * v.g12;
    }
  }
}

// The weights of mode n from lag 1 + first_lag on, beside the history from ring position
// `position` on.
ModeMemory::LagSpan ModeMemory::span(int n, long first_lag, long position) const {
  const std::size_t w = offset_[n] + std::size_t(first_lag), h = offset_[n] + std::size_t(position);
  return {weights_[w11].data() + w,   weights_[w22].data() + w,   weights_[w12].data() + w,
          history_[v1_re].data() + h, history_[v1_im].data() + h, history_[v2_re].data() + h,
          history_[v2_im].data() + h};
}

void ModeMemory::history_sums(int first, int last, ModeHistorySums* out) const {
  for (int n = first; n < last; ++n) {
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    const long size = length_[n];
    const long count = std::min(size, pushed_);
    if (n > 0 && count > 0) {
      // Lags 1 .. count sit at ring positions head, head + 1, ... (wrapping at size).
      const long head = head_[n];
      const long part1 = std::min(count, size - head);
      accumulate(span(n, 0, head), part1, acc);
      accumulate(span(n, part1, 0), count - part1, acc);
    }
    out[n - first] = {{acc[0], acc[1]}, {acc[2], acc[3]}, {acc[4], acc[5]}, {acc[6], acc[7]}};
  }
}

void ModeMemory::push(const std::complex<double>* v1, const std::complex<double>* v2) {
  for (int n = 1; n < modes(); ++n) {
    const long size = length_[n];
    head_[n] = (head_[n] + size - 1) % size; // the newest value becomes lag 1
    const std::size_t at = offset_[n] + std::size_t(head_[n]);
    history_[v1_re][at] = v1[n].real();
    history_[v1_im][at] = v1[n].imag();
    history_[v2_re][at] = v2[n].real();
    history_[v2_im][at] = v2[n].imag();
  }
  ++pushed_;
}

} // namespace slipfront::spectral
