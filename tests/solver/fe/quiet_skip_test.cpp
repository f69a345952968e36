// Skipping the quiet far field (solver/fe/quiet_columns.hpp) changes no bit: the paper's scene
// stepped with the skipping and with every node swept at every step gives the same u, v,
// interface and energy, with and without the mesh damping and the absorbing top; and the
// skipping does leave columns out.
#include "bit_compare.hpp"
#include "scene_support.hpp"

#include "solver/fe/mesh_stepper.hpp"
#include "solver/fe/quiet_columns.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

namespace slipfront::fe {
namespace {

using namespace bits;

struct Variant {
  double mesh_damping;
  TopBoundary top;
  double height;
};

void expect_skipping_changes_no_bit(const Variant& variant) {
  SimulationParams p = verification::paper_scene(10.0, 5e-5, 2);
  p.fe.mesh_damping = variant.mesh_damping;
  p.top = variant.top;
  p.geometry.height = variant.height;
  MeshStepper skipping(p), sweeping(p);
  sweeping.set_skip_quiet(false);
  ThreadTeam team(2);
  const int nx = skipping.nx();
  long narrow_rows = 0; // row-steps that left some, not all, of the row's columns out
  long swept_nodes = 0; // node-updates the skipping made
  for (int n = 0; n < 600; ++n) {
    const bool energy = n % 7 == 0;
    skipping.step(team, energy);
    sweeping.step(team, energy);
    for (int j = 0; j < skipping.ny(); ++j) {
      const int width = skipping.active_columns(j).size();
      narrow_rows += width > 0 && width < nx;
      swept_nodes += width;
    }
    if (n % 50 != 49) continue;
    ASSERT_EQ(differing_nodes(skipping.displacement(), sweeping.displacement()), 0) << "step " << n;
    ASSERT_EQ(differing_nodes(skipping.velocity(), sweeping.velocity()), 0) << "step " << n;
    const InterfaceFields &a = skipping.interface(), &b = sweeping.interface();
    ASSERT_EQ(differing(a.velocity, b.velocity) + differing(a.slip, b.slip) +
                  differing(a.opening, b.opening) + differing(a.shear_traction, b.shear_traction) +
                  differing(a.pressure, b.pressure) + differing(a.strength, b.strength),
              0)
        << "step " << n;
    const EnergyBalance &ea = skipping.energy(), &eb = sweeping.energy();
    ASSERT_TRUE(same_bits(ea.kinetic, eb.kinetic)) << "step " << n;
    ASSERT_TRUE(same_bits(ea.strain, eb.strain)) << "step " << n;
    ASSERT_TRUE(same_bits(ea.external_work, eb.external_work)) << "step " << n;
    ASSERT_TRUE(same_bits(ea.dissipated, eb.dissipated)) << "step " << n;
  }
  EXPECT_GT(skipping.energy().kinetic, 0.0); // the rupture is running
  // The waves have not crossed the 40 m period in 600 steps (c_p dt / dx < 1).
  EXPECT_GT(narrow_rows, 0);
  verification::measure("quiet skipping (n_d=10, damping %g, top %s, h %g m, 600 steps): "
                        "row-steps partly swept = %ld, nodes swept = %.3f of all",
                        variant.mesh_damping,
                        variant.top == TopBoundary::absorbing ? "absorbing"
                        : variant.top == TopBoundary::pml     ? "pml"
                                                              : "traction",
                        variant.height, narrow_rows,
                        double(swept_nodes) / (600.0 * nx * skipping.ny()));
}

TEST(QuietSkipping, ChangesNoBitOnThePaperScene) {
  expect_skipping_changes_no_bit({0.0, TopBoundary::traction, 20.0});
}

TEST(QuietSkipping, ChangesNoBitWithMeshDampingAndAbsorbingTop) {
  // A low block: the waves reach the absorbing top within the run.
  expect_skipping_changes_no_bit({0.1, TopBoundary::absorbing, 3.0});
}

// The perfectly matched layer (20 rows above h = 2 m): its rows hold memory fields beside u
// and v; with the mesh damping too.
TEST(QuietSkipping, ChangesNoBitWithThePerfectlyMatchedLayer) {
  expect_skipping_changes_no_bit({0.0, TopBoundary::pml, 2.0});
  expect_skipping_changes_no_bit({0.1, TopBoundary::pml, 2.0});
}

TEST(QuietSkipping, ChangesNoBitWithATractionTopTheWavesReach) {
  expect_skipping_changes_no_bit({0.0, TopBoundary::traction, 3.0});
}

TEST(QuietColumns, GrowByOneColumnAndCoverTheRowAtThePeriodicBoundary) {
  const int nx = 20;
  std::vector<ColumnRange> now(5);
  now[0] = {8, 10};
  now[1] = {9, 11};
  now[2] = {};
  now[3] = {0, 3}; // touches column 0: its neighbour nx - 1 may change
  now[4] = {};
  EXPECT_EQ(grown_column_range(now, 0, nx).begin, 7); // rows 0, 1 (no row below)
  EXPECT_EQ(grown_column_range(now, 0, nx).end, 12);
  EXPECT_EQ(grown_column_range(now, 1, nx).begin, 7); // hull of rows 0..2 = [8, 11), grown
  EXPECT_EQ(grown_column_range(now, 1, nx).end, 12);
  EXPECT_EQ(grown_column_range(now, 2, nx).begin, 0); // rows 1..3 touch column 0
  EXPECT_EQ(grown_column_range(now, 2, nx).end, nx);
  EXPECT_EQ(grown_column_range(now, 4, nx).size(), nx); // row 3 below it, no row above
  now[3] = {};
  EXPECT_TRUE(grown_column_range(now, 3, nx).empty()); // rows 2..4 are quiet
}

TEST(QuietColumns, TrimToTheNonZeroColumns) {
  VectorField u(10, 2), v(10, 2);
  EXPECT_TRUE(trim_column_range(u, v, 1, {0, 10}).empty());
  u.y.at(3, 1) = 1e-300;
  v.x.at(6, 1) = -2.0;
  const ColumnRange r = trim_column_range(u, v, 1, {1, 9});
  EXPECT_EQ(r.begin, 3);
  EXPECT_EQ(r.end, 7);
}

} // namespace
} // namespace slipfront::fe
