// The cost of one BI step, the rigid plane against two elastic half-spaces (the
// two-solid target: "BI bimaterial at most 2 x today's BI per step"). The paper's scene at n_d
// (1600 nodes at 40), beta = 0.5, one thread; the method is first stepped `warm-up` steps (default:
// 1280, the length of the paper's run at n_d = 40) so that the memory rings hold what a late step
// of a run sums; then each benchmark iteration is one step. Scenes: 0 the rigid plane (today's), 1
// two identical solids (the same dt), 2 the lower solid with the bimaterial presets' contrast (c_s
// x 1.18, density x 1.0055, the same nu): dt = beta dx / c_s of the faster solid, so the upper
// solid keeps 1.18 times more lags per mode. docs/performance.md §6.
//
//   build/bench/slipfront_spectral_step --benchmark_min_time=2
#include "solver/spectral/spectral_method.hpp"

#include <benchmark/benchmark.h>

#include <memory>

namespace {

using namespace slipfront;

SimulationParams scene(double n_d, int which) {
  SimulationParams p;
  p.method = Method::spectral_bi;
  p.geometry.nodes_per_meter = n_d;
  p.threads = 1;
  p.time.duration = 1e6; // never the bound of the memory length
  if (which > 0) {
    p.lower.side = LowerSide::elastic;
    p.lower.material = p.material;
  }
  if (which == 2) {
    const double density = 2745.739 / 2730.834, shear_speed = 3091.6 / 2620.0;
    p.lower.material.density *= density;
    p.lower.material.young_modulus *= density * shear_speed * shear_speed;
  }
  return p;
}

// args: n_d, scene, warm-up steps.
void bi_step(benchmark::State& state) {
  const SimulationParams p = scene(double(state.range(0)), int(state.range(1)));
  spectral::SpectralMethod method(p, 1);
  for (long s = 0; s < state.range(2); ++s)
    method.step(false);
  for (auto _ : state)
    method.step(false);
  state.counters["nodes"] = method.nx();
  state.counters["dt_us"] = method.dt() * 1e6;
}

} // namespace

BENCHMARK(bi_step)
    ->ArgNames({"n_d", "scene", "warmup"})
    ->Args({40, 0, 1280})
    ->Args({40, 1, 1280})
    ->Args({40, 2, 1280})
    ->Args({20, 0, 640})
    ->Args({20, 1, 640})
    ->Args({20, 2, 640})
    ->Args({80, 0, 2560})
    ->Args({80, 2, 2560})
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_MAIN();
