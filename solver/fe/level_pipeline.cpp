#include "solver/fe/level_pipeline.hpp"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace slipfront::fe {

namespace {

// Wait until `progress` reaches `rows`. The thread it waits for is at most a few rows
// ahead, so a short spin usually ends it; yielding after that keeps a loaded (time-sliced)
// machine from wasting the waited-for thread's core.
void wait_for(const std::atomic<int>& progress, int rows) {
  for (int spins = 0; progress.load(std::memory_order_acquire) < rows; ++spins)
    if (spins > 256) std::this_thread::yield();
}

// One member's levels [first, last) in one trip over the rows (the schedule of the header).
void sweep_levels(int member, int first, int last, int rows, const RowStep& row_step,
                  const std::atomic<int>* before, std::atomic<int>& mine) {
  const int span = last - first; // levels of this member
  const int final_front = rows + 2 * (span - 1);
  for (int front = 0; front <= final_front; ++front) {
    for (int q = 0; q < span; ++q) {
      const int level = first + q;
      const int row = front - 2 * q; // this level's velocity row
      if (row < 0 || row > rows) continue;
      // The first level needs the previous member's last level done on rows up to row+1.
      if (q == 0 && before && row < rows) wait_for(*before, std::min(row + 2, rows));
      row_step(level, row, member);
    }
    // Rows [0, front - 2 (span - 1)) are finished at this member's last level.
    mine.store(std::clamp(front - 2 * (span - 1), 0, rows), std::memory_order_release);
  }
}

} // namespace

void run_level_pipeline(ThreadTeam& team, int levels, int rows, const RowStep& row_step) {
  if (levels <= 0 || rows <= 0) return;
  const int members = std::min(team.size(), levels);
  std::vector<std::atomic<int>> progress(members);
  for (auto& p : progress)
    p.store(0, std::memory_order_relaxed);
  team.run([&](int member, int) {
    if (member >= members) return;
    // Contiguous runs of levels of about equal length, the earlier levels to member 0.
    const int first = int(long(levels) * member / members);
    const int last = int(long(levels) * (member + 1) / members);
    sweep_levels(member, first, last, rows, row_step, member > 0 ? &progress[member - 1] : nullptr,
                 progress[member]);
  });
}

} // namespace slipfront::fe
