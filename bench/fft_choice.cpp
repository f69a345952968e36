// Why the spectral BI method uses FFTW3 and not Eigen's FFT (docs/spectral-bi.md): one
// forward + inverse real transform pair at the interface sizes of n_d = 20 .. 320.
//
//   build/bench/slipfront_fft_choice --benchmark_min_time=0.5
#include "solver/spectral/real_fft.hpp"

#include <benchmark/benchmark.h>
#include <unsupported/Eigen/FFT>

#include <cmath>
#include <complex>
#include <vector>

namespace {

std::vector<double> signal(int n) {
  std::vector<double> x(n);
  for (int i = 0; i < n; ++i)
    x[i] = std::sin(0.1 * double(i) * i);
  return x;
}

void fftw_pair(benchmark::State& state) { // as the BI model plans it (FFTW_ESTIMATE)
  const int n = int(state.range(0));
  slipfront::spectral::RealFft fft(n);
  std::vector<double> x = signal(n);
  std::vector<std::complex<double>> X(fft.modes());
  for (auto _ : state) {
    fft.forward(x.data(), X.data());
    fft.inverse(X.data(), x.data());
    benchmark::DoNotOptimize(x.data());
  }
}

void eigen_pair(benchmark::State& state) {
  const int n = int(state.range(0));
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::HalfSpectrum);
  std::vector<double> x = signal(n);
  std::vector<std::complex<double>> X;
  for (auto _ : state) {
    fft.fwd(X, x);
    fft.inv(x, X);
    benchmark::DoNotOptimize(x.data());
  }
}

} // namespace

// N = 40 m x n_d for n_d = 20, 40, 80, 160, 320.
BENCHMARK(fftw_pair)->Arg(800)->Arg(1600)->Arg(3200)->Arg(6400)->Arg(12800);
BENCHMARK(eigen_pair)->Arg(800)->Arg(1600)->Arg(3200)->Arg(6400)->Arg(12800);
BENCHMARK_MAIN();
