#include "solver/quiet_columns.hpp"

#include <algorithm>

namespace slipfront {

void grow_column_ranges(const std::vector<ColumnRange>& now, int first, int rows, int nx,
                        std::vector<ColumnRange>& next) {
  const int ny = int(now.size());
  for (int j = first; j < rows; ++j) {
    int begin = nx, end = 0; // the hull of the non-empty ranges of rows j-1, j, j+1
    for (int r = std::max(0, j - 1); r <= std::min(ny - 1, j + 1); ++r) {
      if (r >= rows || now[r].empty()) continue;
      begin = std::min(begin, now[r].begin);
      end = std::max(end, now[r].end);
    }
    if (end <= begin) {
      next[j] = ColumnRange{};
    } else if (begin == 0 || end == nx) { // would cross the periodic boundary
      next[j] = ColumnRange{0, nx};
    } else {
      next[j] = ColumnRange{begin - 1, end + 1};
    }
  }
}

namespace {

bool column_is_zero(const double* const* rows, int i) {
  return rows[0][i] == 0.0 && rows[1][i] == 0.0 && rows[2][i] == 0.0 && rows[3][i] == 0.0;
}

} // namespace

ColumnRange trim_column_range(const VectorField& u, const VectorField& v, int j,
                              ColumnRange range) {
  const double* rows[4] = {u.x.row(j), u.y.row(j), v.x.row(j), v.y.row(j)};
  int begin = range.begin, end = range.end;
  while (begin < end && column_is_zero(rows, begin))
    ++begin;
  while (end > begin && column_is_zero(rows, end - 1))
    --end;
  return end > begin ? ColumnRange{begin, end} : ColumnRange{};
}

std::vector<int> balanced_row_bands(const std::vector<ColumnRange>& ranges, int rows, int members) {
  constexpr long kRowOverhead = 32;      // a row's fixed cost (calls, ghosts, trimming) in nodes
  std::vector<long> before(rows + 1, 0); // work of rows [0, j)
  for (int j = 0; j < rows; ++j)
    before[j + 1] = before[j] + ranges[j].size() + kRowOverhead;
  std::vector<int> bounds(members + 1, 0);
  bounds[members] = rows;
  for (int m = 1; m < members; ++m) {
    const long target = before[rows] * m / members;
    int b = int(std::lower_bound(before.begin(), before.end(), target) - before.begin());
    b = std::max(b, bounds[m - 1] + 2);        // at least two rows in band m - 1
    b = std::min(b, rows - 2 * (members - m)); // and in each band after it
    bounds[m] = b;
  }
  return bounds;
}

} // namespace slipfront
