#include "solver/fe/quiet_columns.hpp"

#include <algorithm>

namespace slipfront::fe {

ColumnRange grown_column_range(const std::vector<ColumnRange>& now, int j, int nx) {
  const int ny = int(now.size());
  int begin = nx, end = 0; // the hull of the non-empty ranges of rows j-1, j, j+1
  for (int r = std::max(0, j - 1); r <= std::min(ny - 1, j + 1); ++r) {
    if (now[r].empty()) continue;
    begin = std::min(begin, now[r].begin);
    end = std::max(end, now[r].end);
  }
  if (end <= begin) return ColumnRange{};
  if (begin == 0 || end == nx) return ColumnRange{0, nx}; // would cross the periodic boundary
  return ColumnRange{begin - 1, end + 1};
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

} // namespace slipfront::fe
