// Temporal blocking (solver/fe/level_pipeline.hpp): the schedule respects every dependency of
// the row-by-row step, and a mesh advanced several steps per trip, on 1, 2 or 3 threads,
// gives the same bits after every step as the mesh stepped one step at a time.
#include "bit_compare.hpp"
#include "scene_support.hpp"

#include "solver/fe/level_pipeline.hpp"
#include "solver/fe/mesh_stepper.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <memory>

namespace slipfront::fe {
namespace {

// Every (level, row) part made once, and each only when what it reads is ready and what it
// overwrites is no longer read:
//   velocity(k, j)     after displacement(k-1, j-1..j+1)  (u of level k on rows j-1..j+1)
//   displacement(k, j) after velocity(k, j-1..j+1)        (every reader of u_j at level k)
void expect_schedule_respects_dependencies(int threads, int levels, int rows) {
  const int cells = levels * rows;
  std::unique_ptr<std::atomic<int>[]> vel(new std::atomic<int>[cells]),
      disp(new std::atomic<int>[cells]);
  for (int c = 0; c < cells; ++c) {
    vel[c] = 0;
    disp[c] = 0;
  }
  std::atomic<long> violations{0};
  auto done = [&](std::atomic<int>* part, int k, int j) {
    if (k < 0 || j < 0 || j >= rows) return true; // outside: nothing to wait for
    return part[k * rows + j].load(std::memory_order_acquire) == 1;
  };
  ThreadTeam team(threads);
  run_level_pipeline(team, levels, rows, [&](int k, int r, int) {
    if (r < rows) { // the velocity part of row r
      for (int n = r - 1; n <= r + 1; ++n)
        if (!done(disp.get(), k - 1, n)) ++violations;
      if (vel[k * rows + r].fetch_add(1, std::memory_order_acq_rel) != 0) ++violations;
    }
    if (r >= 1) { // the displacement part of row r - 1
      for (int n = r - 2; n <= r; ++n)
        if (!done(vel.get(), k, n)) ++violations;
      if (disp[k * rows + r - 1].fetch_add(1, std::memory_order_acq_rel) != 0) ++violations;
    }
  });
  long missing = 0;
  for (int c = 0; c < cells; ++c)
    missing += (vel[c] != 1) + (disp[c] != 1);
  EXPECT_EQ(violations.load(), 0) << threads << " threads, " << levels << " levels";
  EXPECT_EQ(missing, 0) << threads << " threads, " << levels << " levels";
}

TEST(LevelPipeline, ScheduleRespectsEveryDependency) {
  for (int threads : {1, 2, 3})
    for (int levels : {1, 2, 5, 8})
      for (int rows : {2, 3, 17})
        expect_schedule_respects_dependencies(threads, levels, rows);
}

using namespace bits;

struct Variant {
  double mesh_damping;
  TopBoundary top;
  double height;
  bool skip_quiet;
};

// 400 steps of the paper's scene at n_d = 10: singly on one thread, and in blocks of
// `block` steps on `threads` threads; every step of every block compared.
void expect_blocks_change_no_bit(const Variant& variant, int block, int threads) {
  SimulationParams p = verification::paper_scene(10.0, 5e-5, threads);
  p.fe.mesh_damping = variant.mesh_damping;
  p.top = variant.top;
  p.geometry.height = variant.height;
  MeshStepper single(p), blocked(p);
  single.set_skip_quiet(variant.skip_quiet);
  blocked.set_skip_quiet(variant.skip_quiet);
  ThreadTeam one(1), team(threads);
  const int steps = 400;
  long interface_diffs = 0, energy_diffs = 0, energy_steps = 0;
  for (int n = 0; n < steps; n += block) {
    const int count = std::min(block, steps - n);
    std::vector<bool> energy(count);
    for (int k = 0; k < count; ++k)
      energy[k] = (n + k) % 7 == 0;
    blocked.advance(team, energy);
    for (int k = 0; k < count; ++k) {
      single.step(one, energy[k]);
      interface_diffs += differing_interface(single.interface(), blocked.interface_after(k));
      energy_diffs += differing_energy(single.energy(), blocked.energy_after(k));
      energy_steps += energy[k];
    }
    ASSERT_EQ(interface_diffs, 0) << "block at step " << n;
    ASSERT_EQ(energy_diffs, 0) << "block at step " << n;
    ASSERT_EQ(differing_nodes(single.displacement(), blocked.displacement()), 0) << "step " << n;
    ASSERT_EQ(differing_nodes(single.velocity(), blocked.velocity()), 0) << "step " << n;
  }
  EXPECT_EQ(blocked.steps_done(), steps);
  EXPECT_EQ(blocked.swept_node_updates(), single.swept_node_updates());
  EXPECT_GT(single.energy().kinetic, 0.0); // the rupture is running
  EXPECT_GT(energy_steps, 50);
  verification::measure(
      "temporal blocking (n_d=10, damping %g, top %s, h %g m, skip %d): "
      "%d steps per block on %d threads, 400 steps: differing values = %ld",
      variant.mesh_damping, variant.top == TopBoundary::absorbing ? "absorbing" : "traction",
      variant.height, int(variant.skip_quiet), block, threads, interface_diffs + energy_diffs);
}

TEST(TemporalBlocking, ChangesNoBitOnThePaperScene) {
  const Variant paper{0.0, TopBoundary::traction, 20.0, true};
  expect_blocks_change_no_bit(paper, 8, 2);
  expect_blocks_change_no_bit(paper, 5, 1);
  expect_blocks_change_no_bit(paper, 7, 3);
}

TEST(TemporalBlocking, ChangesNoBitWithMeshDampingAndAbsorbingTop) {
  // A low block: the waves reach the absorbing top within the run.
  expect_blocks_change_no_bit({0.1, TopBoundary::absorbing, 3.0, true}, 8, 2);
  expect_blocks_change_no_bit({0.1, TopBoundary::absorbing, 3.0, true}, 3, 3);
}

TEST(TemporalBlocking, ChangesNoBitWithATractionTopTheWavesReachAndEveryNodeSwept) {
  expect_blocks_change_no_bit({0.0, TopBoundary::traction, 3.0, false}, 8, 2);
  expect_blocks_change_no_bit({0.0, TopBoundary::traction, 3.0, true}, 16, 2);
}

} // namespace
} // namespace slipfront::fe
