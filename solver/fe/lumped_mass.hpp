// The lumped (row-sum) mass of a node of the structured bilinear-quad mesh, per unit
// thickness [kg/m]: rho dx^2 in the bulk, half of it on the bottom and top rows (each of
// their nodes touches two elements instead of four).
#pragma once

namespace slipfront::fe {

inline double lumped_node_mass(int row, int rows, double dx, double density) {
  const double full = density * dx * dx;
  return (row == 0 || row == rows - 1) ? 0.5 * full : full;
}

} // namespace slipfront::fe
