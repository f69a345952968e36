// The BI method's dominant cost: the per-mode memory sums (solver/spectral/mode_memory.cpp),
// one sweep over every mode with its history full, on the paper's scene. Reports the lags
// summed per second and the bytes streamed (56 B a lag: 3 weights and 4 history values, in
// doubles) against the machine's cache and memory bandwidth (docs/performance.md §6).
//
//   build/bench/slipfront_spectral_memory --benchmark_min_time=1
#include "solver/params.hpp"
#include "solver/spectral/mode_memory.hpp"
#include "solver/spectral/spectral_method.hpp"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <complex>
#include <random>
#include <vector>

namespace {

using namespace slipfront;

// args: n_d, time_step_factor x 1000.
void memory_sums(benchmark::State& state) {
  SimulationParams p;
  p.method = Method::spectral_bi;
  p.geometry.nodes_per_meter = double(state.range(0));
  p.spectral.time_step_factor = double(state.range(1)) / 1000.0;
  const int nx = int(p.geometry.width * p.geometry.nodes_per_meter), modes = nx / 2 + 1;
  const double dt = spectral::SpectralMethod::time_step(p);
  const long steps = spectral::SpectralMethod::max_steps(p);
  const double cs = p.material.s_wave_speed();
  const spectral::HalfSpaceKernels kernels(cs / p.material.p_wave_speed(),
                                           spectral::SpectralMethod::kernel_span(p));
  spectral::ModeMemory memory(modes, p.geometry.width, dt, cs, p.material.density * cs,
                              p.spectral.memory_periods, steps, kernels);

  // Fill every ring with random velocities (the sums' cost does not depend on the values).
  std::mt19937_64 random(7);
  std::normal_distribution<double> normal;
  std::vector<std::complex<double>> v1(modes), v2(modes);
  long longest = 0;
  for (int n = 0; n < modes; ++n)
    longest = std::max(longest, memory.length(n));
  for (long s = 0; s < longest; ++s) {
    for (int n = 0; n < modes; ++n)
      v1[n] = {normal(random), normal(random)}, v2[n] = {normal(random), normal(random)};
    memory.push(v1.data(), v2.data());
  }

  std::vector<spectral::ModeHistorySums> sums(modes);
  for (auto _ : state) {
    memory.history_sums(0, modes, sums.data());
    benchmark::DoNotOptimize(sums.data());
  }
  const double lags = double(memory.stored_values()) / 4.0;
  state.counters["lags"] = lags;
  state.counters["lags_per_s"] =
      benchmark::Counter(lags * double(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["bytes_per_s"] =
      benchmark::Counter(56.0 * lags * double(state.iterations()), benchmark::Counter::kIsRate,
                         benchmark::Counter::kIs1024);
}

} // namespace

// (n_d, beta): the cheapest run at FE n_d = 40's accuracy, and the default step at 20..160.
BENCHMARK(memory_sums)
    ->Args({20, 125})
    ->Args({20, 500})
    ->Args({40, 500})
    ->Args({80, 500})
    ->Args({160, 500})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
