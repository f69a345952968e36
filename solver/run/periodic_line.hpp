// The periodic line of interface nodes x_min + i dx, i = 0 .. nx-1: an index wrapped onto it,
// the node nearest to a position, and a nodal quantity read between two nodes.
#pragma once

#include <vector>

namespace slipfront {

// Index of node i on a periodic line of n nodes: i wrapped into [0, n), for any sign of i.
inline int periodic_index(long i, int n) {
  return int(((i % n) + n) % n);
}

// The two nodes around x1 on the periodic line of nx nodes x_min + i dx: `left` at or below
// x1, `right` the next one (wrapped), and the weight of `right` in [0, 1): a nodal quantity at
// x1 is (1 - weight) f(left) + weight f(right).
struct NodePair {
  int left = 0;
  int right = 0;
  double weight = 0.0;
};
NodePair nodes_around(double x1, double x_min, double dx, int nx);

// The node nearest to x1 on the periodic line of nx nodes x_min + i dx.
int nearest_node(double x1, double x_min, double dx, int nx);

// Value at x1 of a nodal quantity, linear between the two nodes around x1 (NaN if either is).
double interpolate_nodal(const std::vector<double>& values, double x1, double x_min, double dx);

} // namespace slipfront
