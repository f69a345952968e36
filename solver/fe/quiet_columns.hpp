// The quiet far field along x1: per row, the columns that may hold non-zero values.
//
// In the explicit step a node's u and v change only if its own v or the u of one of its
// eight neighbours is non-zero (the 9-point stencil, solver/fe/stencil.hpp). So if every
// non-zero node of row j lies in columns [begin, end) of that row (its ColumnRange), after
// one step the non-zero nodes of row j lie in the hull of the ranges of rows j-1, j, j+1
// grown by one column on each side: the stencil's light cone, one node per step. Nodes
// outside it hold exact zeros and keep them, so leaving them out of the sweep gives the
// same bits as sweeping them (docs/performance.md §1). After the step each range is trimmed
// to the columns that really are non-zero (far ahead of the physical waves the values
// underflow to zero: the solver's threads flush denormals).
//
// The ranges do not wrap around the periodic boundary: a range that would cross it becomes
// the whole row (node 0 and node nx-1 are neighbours through the ghost nodes).
#pragma once

#include "solver/fe/nodal_field.hpp"

#include <vector>

namespace slipfront::fe {

struct ColumnRange {
  int begin = 0, end = 0; // columns [begin, end); empty if end <= begin
  bool empty() const { return end <= begin; }
  int size() const { return empty() ? 0 : end - begin; }
};

// The range of row j after one step, from the ranges of rows j-1, j, j+1 before it: their
// hull grown by one column each side (the whole row if it would cross the periodic
// boundary; empty if all three are).
ColumnRange grown_column_range(const std::vector<ColumnRange>& now, int j, int nx);

// `range` narrowed to the columns where u or v of row j is non-zero (empty if none).
ColumnRange trim_column_range(const VectorField& u, const VectorField& v, int j, ColumnRange range);

} // namespace slipfront::fe
