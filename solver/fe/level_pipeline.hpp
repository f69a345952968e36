// Temporal blocking of a row-by-row explicit step: several time steps ("levels") advanced
// in one trip over the rows, so that each row comes from memory once for all of them.
//
// A step advances row j in two parts (solver/fe/mesh_stepper.hpp):
//   velocity part:      reads the displacement of rows j-1, j, j+1 at this level, writes
//                       row j's velocity;
//   displacement part:  advances row j's displacement to the next level, in place.
// So row j's displacement part may run only once row j+1's velocity part has read it, and
// level k+1's velocity part of row j needs level k's displacement part done on rows up to
// j+1. One trip carries the levels two rows apart: at front position J, level k makes its
// row step J - 2k: the velocity part of row J - 2k and then the displacement part of row
// J - 2k - 1 (the two may be interleaved column by column, solver/fe/mesh_stepper.cpp). The
// rows between the first and the last level (about 2 per level) stay in cache.
//
// With several threads each takes a contiguous run of the levels and follows the thread
// before it, waiting (briefly spinning, then yielding) on that thread's progress: the
// number of rows its last level has finished. There are no band edges: every row operation
// is the one of a step-by-step sweep, made once, so the result has the same bits for any
// number of levels per trip and any number of threads (tests/solver/fe/level_pipeline_test.cpp).
#pragma once

#include "solver/thread_team.hpp"

#include <functional>

namespace slipfront::fe {

// row_step(level, r, member), for r = 0 .. rows: the velocity part of row r (if r < rows),
// then the displacement part of row r - 1 (if r >= 1), on team member `member`.
using RowStep = std::function<void(int level, int r, int member)>;

// Advance `rows` rows through levels [0, levels): row_step(level, r, ...) for every level
// and r = 0 .. rows, in an order that respects the dependencies above. Uses up to
// min(team.size(), levels) members; returns when all are done.
void run_level_pipeline(ThreadTeam& team, int levels, int rows, const RowStep& row_step);

} // namespace slipfront::fe
