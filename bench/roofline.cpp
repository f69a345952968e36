// How close is the solver's time step to the machine's memory-bandwidth limit?
//
// Prints, in one run on one machine:
//   1. STREAM-like triad bandwidth a[i] = b[i] + s c[i] with 1 and 2 threads
//      (24 bytes per element counted, as STREAM does);
//   2. the bytes a node update must move at the least for the solver's layout: u and v,
//      two doubles each, read once and written once = 64 bytes;
//   3. the floor (node updates per second) that bandwidth / 64 implies;
//   4. the solver's node updates per second on the paper's grid (n_d = 40: 1600 x 801
//      nodes, every row active) with 1 and 2 threads, for 1, 2, 4, 8 and 16 steps per
//      thread in a trip over the mesh (temporal blocking, solver/fe/level_pipeline.hpp; 1 is
//      one step per trip), and the ratio actual / floor;
//   5. the effective rate of the paper's run from rest (nucleation on, the quiet far field
//      skipped, the run's steps per trip): every node of the grid counted at every step, as
//      if it had been swept, over the first --paper-steps steps (1793: the run arrests
//      there), and its ratio to the same floor.
//
// Usage: slipfront_roofline [--nodes-per-meter 40] [--steps 64] [--repeats 5]
//                           [--paper-steps 1793]
#include "solver/fe/finite_element_method.hpp"
#include "solver/fe/mesh_stepper.hpp"
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
using namespace slipfront::fe;
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

// `steps` steps in trips of `per_trip` steps (the last trip shorter); energy terms in the
// steps `energy_every` apart (0: none).
void advance(MeshStepper& mesh, ThreadTeam& team, int per_trip, int steps, int energy_every) {
  std::vector<bool> energy;
  for (int done = 0; done < steps;) {
    const int count = std::min(per_trip, steps - done);
    energy.assign(count, false);
    for (int k = 0; k < count && energy_every > 0; ++k)
      energy[k] = (done + k) % energy_every == 0;
    mesh.advance(team, energy);
    done += count;
  }
}

// Best-of-`repeats` node updates per second of MeshStepper::advance on the paper's grid,
// `per_thread` steps per thread in each trip.
double solver_node_updates(double nodes_per_meter, int threads, int per_thread, int steps,
                           int repeats) {
  SimulationParams p;
  p.geometry.nodes_per_meter = nodes_per_meter;
  p.nucleation.enabled = false;
  MeshStepper mesh(p);
  // A smooth, non-zero field everywhere so that every row is active and no value is a
  // denormal (the real run's far field is flushed to zero).
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> small(-1e-6, 1e-6);
  for (int j = 1; j < mesh.ny(); ++j)
    for (int i = 0; i < mesh.nx(); ++i) {
      mesh.displacement().x.at(i, j) = small(rng);
      mesh.displacement().y.at(i, j) = small(rng);
    }
  mesh.displacement().x.refresh_all_ghosts();
  mesh.displacement().y.refresh_all_ghosts();
  mesh.activate_all_rows();
  ThreadTeam team(threads);
  const int per_trip = threads * per_thread;
  advance(mesh, team, per_trip, per_trip, 0); // warm up
  double best = 1e30;
  for (int r = 0; r < repeats; ++r) {
    const auto t0 = Clock::now();
    advance(mesh, team, per_trip, steps, 0);
    best = std::min(best, seconds_since(t0) / steps);
  }
  return double(mesh.nx()) * mesh.ny() / best;
}

struct PaperRun {
  double effective;     // nx ny steps / wall time [node updates/s]
  double cpu_effective; // nx ny steps / CPU time of the process (all threads)
  double swept;         // node updates made / nx ny steps
  double swept_rows;    // the same with whole active rows swept (the skipping in x2 alone)
};

// The paper's run from rest, stepped as a run steps it (FiniteElementMethod's trips).
PaperRun paper_run(double nodes_per_meter, int threads, int steps) {
  SimulationParams p; // the paper's scene
  p.geometry.nodes_per_meter = nodes_per_meter;
  FloatModeGuard float_mode; // as run_simulation: the stepper is built with denormals flushed
  MeshStepper mesh(p);
  ThreadTeam team(threads);
  double row_skip_updates = 0;
  const int per_trip = threads * kFeStepsPerThreadPerTrip;
  const std::clock_t c0 = std::clock();
  const auto t0 = Clock::now();
  std::vector<bool> energy;
  for (int s = 0; s < steps; s += per_trip) {
    const int count = std::min(per_trip, steps - s);
    row_skip_updates += double(count) * std::min(mesh.ny(), mesh.active_rows() + count) * mesh.nx();
    energy.assign(count, false);
    for (int k = 0; k < count; ++k)
      energy[k] = (s + k) % 7 == 0; // the energy terms about as often as a run evaluates them
    mesh.advance(team, energy);
  }
  const double wall = seconds_since(t0);
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  const double all = double(mesh.nx()) * mesh.ny() * steps;
  return {all / wall, all / cpu, double(mesh.swept_node_updates()) / all, row_skip_updates / all};
}

} // namespace

int main(int argc, char** argv) {
  double nd = 40;
  int steps = 64, repeats = 5, paper_steps = 1793;
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
  const int per_thread_list[] = {1, 2, 4, 8, 16};
  for (int threads : {1, 2}) {
    const double bw = triad_bandwidth(threads, triad_n, repeats);
    const double floor = bw / bytes_per_node;
    std::printf("\n%d thread%s: triad %.2f GB/s, floor %.1f Mnode-upd/s\n", threads,
                threads > 1 ? "s" : "", bw / 1e9, floor / 1e6);
    std::printf("  %-26s %22s %8s\n", "steps per thread per trip", "solver [Mnode-upd/s]", "ratio");
    for (int per_thread : per_thread_list) {
      const double actual = solver_node_updates(nd, threads, per_thread, steps, repeats);
      std::printf("  %-26d %22.1f %8.2f%s\n", per_thread, actual / 1e6, actual / floor,
                  per_thread == kFeStepsPerThreadPerTrip ? "   (the runs' setting)" : "");
    }
    if (paper_steps <= 0) continue;
    const PaperRun paper = paper_run(nd, threads, paper_steps);
    std::printf("  paper run: effective %.1f Mnode-upd/s = %.2f x floor; per CPU second %.1f; "
                "node updates made: %.3f of nx ny steps (%.3f with whole rows swept)\n",
                paper.effective / 1e6, paper.effective / floor, paper.cpu_effective / 1e6,
                paper.swept, paper.swept_rows);
  }
  std::printf("grid: n_d = %g (%d x %d nodes at the paper's 40 m x 20 m); paper run: the first "
              "%d steps from rest\n",
              nd, int(40 * nd), int(20 * nd) + 1, paper_steps);
  return 0;
}
