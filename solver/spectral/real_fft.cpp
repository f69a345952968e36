#include "solver/spectral/real_fft.hpp"

#include <fftw3.h>

#include <algorithm>
#include <mutex>
#include <stdexcept>

namespace slipfront::spectral {

namespace {
// FFTW's planner is not thread-safe (fftw_execute is): worker threads plan one at a time.
std::mutex& planner_mutex() {
  static std::mutex m;
  return m;
}
} // namespace

RealFft::RealFft(int n) : n_(n), real_(n), complex_(n / 2 + 1) {
  if (n < 2) throw std::invalid_argument("FFT length must be at least 2");
  auto* c = reinterpret_cast<fftw_complex*>(complex_.data());
  std::lock_guard lock(planner_mutex());
  forward_plan_ = fftw_plan_dft_r2c_1d(n, real_.data(), c, FFTW_ESTIMATE);
  inverse_plan_ = fftw_plan_dft_c2r_1d(n, c, real_.data(), FFTW_ESTIMATE);
  if (!forward_plan_ || !inverse_plan_) throw std::runtime_error("FFTW could not plan the FFT");
}

RealFft::~RealFft() {
  std::lock_guard lock(planner_mutex());
  fftw_destroy_plan(static_cast<fftw_plan>(forward_plan_));
  fftw_destroy_plan(static_cast<fftw_plan>(inverse_plan_));
}

void RealFft::forward(const double* x, std::complex<double>* spectrum) {
  std::copy(x, x + n_, real_.begin());
  fftw_execute(static_cast<fftw_plan>(forward_plan_));
  std::copy(complex_.begin(), complex_.end(), spectrum);
}

void RealFft::inverse(const std::complex<double>* spectrum, double* x) {
  std::copy(spectrum, spectrum + modes(), complex_.begin()); // c2r overwrites its input
  fftw_execute(static_cast<fftw_plan>(inverse_plan_));
  const double scale = 1.0 / n_;
  for (int j = 0; j < n_; ++j)
    x[j] = real_[j] * scale;
}

} // namespace slipfront::spectral
