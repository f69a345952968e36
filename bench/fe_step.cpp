// The cost of the FE step, one block on the rigid plane against two equal blocks (the
// two-block target: "FE with two blocks at most 2.2 x today's single-block step per interface
// column"). The paper's scene at n_d (1600 columns at 40), both blocks h high (20 m: the paper's),
// one thread, every node swept (quiet skipping off: the cost of a run once the waves fill the
// blocks, not of its first steps); each benchmark iteration is one trip of `steps` steps over the
// mesh (temporal blocking as the run does it, solver/fe/level_pipeline.hpp). Scenes: 0 the rigid
// plane (today's), 1 two identical blocks, 2 the lower block with the bimaterial presets'
// contrast (c_s x 1.18, density x 1.0055, the same nu; dt of the faster solid).
// The counter column_steps is what one iteration does: steps x interface columns.
// docs/performance.md "The FE step with two blocks".
//
//   build/bench/slipfront_fe_step --benchmark_min_time=2
#include "solver/fe/mesh_stepper.hpp"

#include <benchmark/benchmark.h>

namespace {

using namespace slipfront;

SimulationParams scene(double n_d, int which, double height, int threads) {
  SimulationParams p;
  p.geometry.nodes_per_meter = n_d;
  p.geometry.height = height;
  p.threads = threads;
  if (which > 0) {
    p.lower.side = LowerSide::elastic;
    p.lower.material = p.material;
    p.lower.height = p.geometry.height;
  }
  if (which == 2) {
    const double density = 2745.739 / 2730.834, shear_speed = 3091.6 / 2620.0;
    p.lower.material.density *= density;
    p.lower.material.young_modulus *= density * shear_speed * shear_speed;
  }
  return p;
}

// args: n_d, scene, steps per trip, height of each block [m], threads.
void fe_step(benchmark::State& state) {
  const int threads = int(state.range(4));
  const SimulationParams p =
      scene(double(state.range(0)), int(state.range(1)), double(state.range(3)), threads);
  fe::MeshStepper mesh(p);
  mesh.set_skip_quiet(false);
  ThreadTeam team(threads);
  const std::vector<bool> energy(std::size_t(state.range(2)), false);
  for (int k = 0; k < 20; ++k) // the rupture under way
    mesh.advance(team, energy);
  for (auto _ : state)
    mesh.advance(team, energy);
  // Divide the time per iteration by this: the time per interface column and step.
  state.counters["column_steps"] = double(energy.size()) * mesh.nx();
  state.counters["rows"] = mesh.ny() + (mesh.lower() ? mesh.lower()->ny() : 0);
}

} // namespace

BENCHMARK(fe_step)
    ->ArgNames({"n_d", "scene", "steps", "h", "threads"})
    ->Args({20, 0, 4, 20, 1})
    ->Args({20, 1, 4, 20, 1})
    ->Args({20, 2, 4, 20, 1})
    ->Args({20, 0, 4, 40, 1}) // one block as many nodes as the two: the cost of the state's size
    ->Args({40, 0, 4, 20, 1})
    ->Args({40, 1, 4, 20, 1})
    ->Args({40, 2, 4, 20, 1})
    ->Args({40, 0, 1, 20, 1})
    ->Args({40, 1, 1, 20, 1})
    ->Args({40, 0, 4, 40, 1})
    ->Args({40, 0, 4, 1, 1}) // low blocks: the interface row's share
    ->Args({40, 1, 4, 1, 1})
    // as a run on two cores steps: 2 threads, 4 steps each per trip
    ->Args({20, 0, 8, 20, 2})
    ->Args({20, 1, 8, 20, 2})
    ->Args({20, 0, 8, 40, 2})
    ->Args({40, 0, 8, 20, 2})
    ->Args({40, 1, 8, 20, 2})
    ->Args({40, 0, 8, 40, 2})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

BENCHMARK_MAIN();
