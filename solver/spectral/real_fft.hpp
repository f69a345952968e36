// Real-to-complex FFT of a fixed length (FFTW3, planned with FFTW_ESTIMATE so that the same
// input gives the same bits in every run; chosen over Eigen's FFT by measurement,
// docs/performance.md).
//
//   RealFft fft(n);
//   fft.forward(x, X);   // X_k = sum_j x_j exp(-2 pi i j k / n), k = 0 .. n/2
//   fft.inverse(X, x);   // x_j = (1/n) sum_k X_k exp(+2 pi i j k / n) (the inverse, normalised)
#pragma once

#include <complex>
#include <vector>

namespace slipfront::spectral {

class RealFft {
public:
  explicit RealFft(int n);
  ~RealFft();
  RealFft(const RealFft&) = delete;
  RealFft& operator=(const RealFft&) = delete;

  int size() const { return n_; }
  int modes() const { return n_ / 2 + 1; }
  void forward(const double* x, std::complex<double>* spectrum);
  void inverse(const std::complex<double>* spectrum, double* x);

private:
  int n_;
  std::vector<double> real_;
  std::vector<std::complex<double>> complex_;
  void* forward_plan_ = nullptr;
  void* inverse_plan_ = nullptr;
};

} // namespace slipfront::spectral
