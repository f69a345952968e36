// How close is the solver's time step to the machine's memory-bandwidth limit?
//
// Prints, in one run on one machine:
//   1. STREAM-like triad bandwidth a[i] = b[i] + s c[i] with 1 and 2 threads
//      (24 bytes per element counted, as STREAM does);
//   2. the bytes a node update must move at the least for the solver's layout: u and v,
//      two doubles each, read once and written once = 64 bytes;
//   3. the floor (node updates per second) that bandwidth / 64 implies;
//   4. the solver's node updates per second on the paper's grid (n_d = 40: 1600 x 801
//      nodes, every row active) with 1 and 2 threads, and the ratio actual / floor;
//   5. the effective rate of the paper's run from rest (nucleation on, the quiet far field
//      skipped): every node of the grid counted at every step, as if it had been swept,
//      over the first --paper-steps steps (1793: the run arrests there), and its ratio to
//      the same floor.
//
// Usage: slipfront_roofline [--nodes-per-meter 40] [--steps 60] [--repeats 5]
//                           [--paper-steps 1793]
#include "solver/rupture_model.hpp"
#include "solver/thread_team.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <vector>

using namespace slipfront;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Best-of-`repeats` triad bandwidth [bytes/s] with `threads` threads over arrays far larger
// than the caches. Each thread touches (first-touch) and streams its own slice.
double triad_bandwidth(int threads, std::size_t n, int repeats) {
  std::vector<double> a(n), b(n), c(n);
  ThreadTeam team(threads);
  auto slice = [&](int m, int size) {
    return std::pair<std::size_t, std::size_t>{n * m / size, n * (m + 1) / size};
  };
  team.run([&](int m, int size) {
    auto [lo, hi] = slice(m, size);
    for (std::size_t i = lo; i < hi; ++i)
      a[i] = 0.0, b[i] = 1.0, c[i] = 2.0;
  });
  const double s = 3.0;
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    team.run([&](int m, int size) {
      auto [lo, hi] = slice(m, size);
      double* __restrict pa = a.data();
      const double* __restrict pb = b.data();
      const double* __restrict pc = c.data();
      for (std::size_t i = lo; i < hi; ++i)
        pa[i] = pb[i] + s * pc[i];
    });
    best = std::min(best, seconds_since(t0));
  }
  if (a[n / 2] != 7.0) std::fprintf(stderr, "triad check failed\n");
  return 24.0 * double(n) / best;
}

// Best-of-`repeats` node updates per second of RuptureModel::step on the paper's grid.
double solver_node_updates(double nodes_per_meter, int threads, int steps, int repeats) {
  SimulationParams p;
  p.geometry.nodes_per_meter = nodes_per_meter;
  p.nucleation.enabled = false;
  RuptureModel model(p);
  // A smooth, non-zero field everywhere so that every row is active and no value is a
  // denormal (the real run's far field is flushed to zero).
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> small(-1e-6, 1e-6);
  for (int j = 1; j < model.ny(); ++j)
    for (int i = 0; i < model.nx(); ++i) {
      model.displacement().x.at(i, j) = small(rng);
      model.displacement().y.at(i, j) = small(rng);
    }
  model.displacement().x.refresh_all_ghosts();
  model.displacement().y.refresh_all_ghosts();
  model.activate_all_rows();
  ThreadTeam team(threads);
  for (int s = 0; s < 5; ++s)
    model.step(team, false); // warm up
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    for (int s = 0; s < steps; ++s)
      model.step(team, false);
    best = std::min(best, seconds_since(t0) / steps);
  }
  return double(model.nx()) * model.ny() / best;
}

struct PaperRun {
  double effective;     // nx ny steps / wall time [node updates/s]
  double cpu_effective; // nx ny steps / CPU time of the process (all threads)
  double swept;         // node updates made / nx ny steps
  double swept_rows;    // the same with whole active rows swept (the skipping in x2 alone)
};

// The paper's run from rest, stepped as a run steps it.
PaperRun paper_run(double nodes_per_meter, int threads, int steps) {
  SimulationParams p; // the paper's scene
  p.geometry.nodes_per_meter = nodes_per_meter;
  FloatModeGuard float_mode; // as run_simulation: the model is built with denormals flushed
  RuptureModel model(p);
  ThreadTeam team(threads);
  double row_skip_updates = 0;
  const std::clock_t c0 = std::clock();
  const auto t0 = Clock::now();
  for (int s = 0; s < steps; ++s) {
    row_skip_updates += double(std::min(model.ny(), model.active_rows() + 1)) * model.nx();
    model.step(team, s % 7 == 0); // the energy terms about as often as a run evaluates them
  }
  const double wall = seconds_since(t0);
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const double all = double(model.nx()) * model.ny() * steps;
  return {all / wall, all / cpu, double(model.swept_node_updates()) / all, row_skip_updates / all};
}

} // namespace

int main(int argc, char** argv) {
  double nd = 40;
  int steps = 60, repeats = 5, paper_steps = 1793;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    if (flag == "--nodes-per-meter")
      nd = std::atof(argv[i + 1]);
    else if (flag == "--steps")
      steps = std::atoi(argv[i + 1]);
    else if (flag == "--repeats")
      repeats = std::atoi(argv[i + 1]);
    else if (flag == "--paper-steps")
      paper_steps = std::atoi(argv[i + 1]);
    else {
      std::fprintf(stderr, "unknown option %s\n", argv[i]);
      return 2;
    }
  }
  const double bytes_per_node = 64.0; // u, v: 2 components x 8 bytes, read + write each
  const std::size_t triad_n = 40u * 1000u * 1000u; // 3 x 320 MB
  std::printf("slipfront roofline: explicit step vs memory bandwidth\n");
  std::printf("layout: u and v as doubles (SoA), each read once and written once per step: "
              "%.0f bytes/node-update at the least\n",
              bytes_per_node);
  std::printf("%-8s %16s %20s %22s %8s %26s %8s\n", "threads", "triad [GB/s]",
              "floor [Mnode-upd/s]", "solver [Mnode-upd/s]", "ratio",
              "paper run eff. [Mnode-upd/s]", "ratio");
  for (int threads : {1, 2}) {
    const double bw = triad_bandwidth(threads, triad_n, repeats);
    const double floor = bw / bytes_per_node;
    const double actual = solver_node_updates(nd, threads, steps, repeats);
    const PaperRun paper = paper_steps > 0 ? paper_run(nd, threads, paper_steps) : PaperRun{};
    std::printf("%-8d %16.2f %20.1f %22.1f %8.2f %26.1f %8.2f\n", threads, bw / 1e9, floor / 1e6,
                actual / 1e6, actual / floor, paper.effective / 1e6, paper.effective / floor);
    std::printf("         paper run: CPU-time effective rate %.1f Mnode-upd/s; node updates made: "
                "%.3f of nx ny steps (%.3f with whole rows swept)\n",
                paper.cpu_effective / 1e6, paper.swept, paper.swept_rows);
  }
  std::printf("grid: n_d = %g (%d x %d nodes at the paper's 40 m x 20 m); paper run: the first "
              "%d steps from rest\n",
              nd, int(40 * nd), int(20 * nd) + 1, paper_steps);
  return 0;
}
