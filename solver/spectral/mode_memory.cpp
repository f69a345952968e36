#include "solver/spectral/mode_memory.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slipfront::spectral {

namespace {

// acc += sum over `count` lags of the weights times the history (8 real sums).
inline void accumulate(const double* __restrict w, const double* __restrict h, long count,
                       double* __restrict acc) {
  double a0 = 0, a1 = 0, a2 = 0, a3 = 0, b0 = 0, b1 = 0, b2 = 0, b3 = 0;
  for (long m = 0; m < count; ++m) {
    const double w11 = w[3 * m], w22 = w[3 * m + 1], w12 = w[3 * m + 2];
    const double v1r = h[4 * m], v1i = h[4 * m + 1], v2r = h[4 * m + 2], v2i = h[4 * m + 3];
    a0 += w11 * v1r;
    a1 += w11 * v1i;
    a2 += w22 * v2r;
    a3 += w22 * v2i;
    b0 += w12 * v2r;
    b1 += w12 * v2i;
    b2 += w12 * v1r;
    b3 += w12 * v1i;
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
  return std::clamp(long(std::ceil(window / dt)), 1L, std::max(1L, max_steps));
}

ModeMemory::ModeMemory(int modes, double width, double dt, double shear_speed, double impedance_s,
                       double memory_periods, long max_steps, const HalfSpaceKernels& kernels)
    : length_(modes, 0), offset_(modes + 1, 0), head_(modes, 0), w0_(modes) {
  const double two_pi = 2.0 * std::numbers::pi;
  for (int n = 1; n < modes; ++n) {
    length_[n] = memory_length(n, width, dt, shear_speed, memory_periods, max_steps);
    offset_[n + 1] = offset_[n] + std::size_t(length_[n]);
  }
  history_.assign(4 * offset_[modes], 0.0);
  weights_.assign(3 * offset_[modes], 0.0);

  for (int n = 1; n < modes; ++n) {
    const double scale = shear_speed * two_pi * n / width * dt; // T per step
    // mu |k| W = (mu / c_s) int g dT = impedance_s * int g dT.
    const KernelValues first = kernels.integral(0.0, 0.5 * scale);
    w0_[n] = {impedance_s * first.g11, impedance_s * first.g22, impedance_s * first.g12, 0, 0, 0};
    double* w = weights_.data() + 3 * offset_[n];
    for (long m = 1; m <= length_[n]; ++m) {
      const KernelValues v = kernels.integral((m - 0.5) * scale, (m + 0.5) * scale);
      w[3 * (m - 1)] = impedance_s * v.g11;
      w[3 * (m - 1) + 1] = impedance_s * v.g22;
      w[3 * (m - 1) + 2] = impedance_s * v.g12;
    }
  }
}

void ModeMemory::history_sums(int first, int last, ModeHistorySums* out) const {
  for (int n = first; n < last; ++n) {
    double acc[8] = {0, 0, 0, 0, 0, 0, 0, 0};
    const long size = length_[n];
    const long count = std::min(size, pushed_);
    if (n > 0 && count > 0) {
      const double* h = history_.data() + 4 * offset_[n];
      const double* w = weights_.data() + 3 * offset_[n];
      // Lags 1 .. count sit at ring positions head, head + 1, ... (wrapping at size).
      const long head = head_[n];
      const long part1 = std::min(count, size - head);
      accumulate(w, h + 4 * head, part1, acc);
      accumulate(w + 3 * part1, h, count - part1, acc);
    }
    out[n - first] = {{acc[0], acc[1]}, {acc[2], acc[3]}, {acc[4], acc[5]}, {acc[6], acc[7]}};
  }
}

void ModeMemory::push(const std::complex<double>* v1, const std::complex<double>* v2) {
  for (int n = 1; n < modes(); ++n) {
    const long size = length_[n];
    head_[n] = (head_[n] + size - 1) % size; // the newest value becomes lag 1
    double* h = history_.data() + 4 * (offset_[n] + std::size_t(head_[n]));
    h[0] = v1[n].real();
    h[1] = v1[n].imag();
    h[2] = v2[n].real();
    h[3] = v2[n].imag();
  }
  ++pushed_;
}

} // namespace slipfront::spectral
