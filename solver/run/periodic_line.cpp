#include "solver/run/periodic_line.hpp"

#include <cmath>

namespace slipfront {

int nearest_node(double x1, double x_min, double dx, int nx) {
  return periodic_index(std::lround((x1 - x_min) / dx), nx);
}

NodePair nodes_around(double x1, double x_min, double dx, int nx) {
  const double s = (x1 - x_min) / dx;
  const long i0 = long(std::floor(s));
  return {periodic_index(i0, nx), periodic_index(i0 + 1, nx), s - double(i0)};
}

double interpolate_nodal(const std::vector<double>& values, double x1, double x_min, double dx) {
  const NodePair p = nodes_around(x1, x_min, dx, int(values.size()));
  if (p.weight < 1e-9) return values[p.left];
  return (1 - p.weight) * values[p.left] + p.weight * values[p.right];
}

} // namespace slipfront
