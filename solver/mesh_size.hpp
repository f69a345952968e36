// Node counts of the regular mesh from the geometry: the FE mesh, the BI interface (its row
// 0) and the size estimates of a run all take them from here.
#pragma once

#include "solver/params.hpp"

#include <cmath>

namespace slipfront {

struct MeshSize {
  int nx; // nodes along x1 (periodic: width / dx elements, as many nodes)
  int ny; // nodes along x2: height / dx elements + 1
  double dx;
  double height;
};

// Height for "auto": the smallest h with 2 h / c_p >= duration (a P wave reflected by the top
// cannot reach the interface before the run ends), in whole elements, plus one element.
inline double auto_height(const SimulationParams& p) {
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  const double h = 0.5 * p.material.p_wave_speed() * p.time.duration;
  return (std::ceil(h / dx - 1e-9) + 1.0) * dx;
}

inline MeshSize mesh_size(const SimulationParams& p) {
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  const double height = p.geometry.auto_height ? auto_height(p) : p.geometry.height;
  MeshSize m;
  m.dx = dx;
  m.nx = int(std::lround(p.geometry.width / dx));
  m.ny = int(std::lround(height / dx)) + 1;
  m.height = (m.ny - 1) * dx;
  return m;
}

} // namespace slipfront
