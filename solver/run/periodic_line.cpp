#include "solver/run/periodic_line.hpp"

#include <cmath>

namespace slipfront {

int nearest_node(double x1, double x_min, double dx, int nx) {
  return periodic_index(std::lround((x1 - x_min) / dx), nx);
}

double interpolate_nodal(const std::vector<double>& values, double x1, double x_min, double dx) {
  const int nx = int(values.size());
  const double s = (x1 - x_min) / dx;
  const long i0 = long(std::floor(s));
  const double w = s - double(i0);
  auto at = [&](long i) { return values[periodic_index(i, nx)]; };
  if (w < 1e-9) return at(i0);
  return (1 - w) * at(i0) + w * at(i0 + 1);
}

} // namespace slipfront
