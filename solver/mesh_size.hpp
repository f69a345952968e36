// Node counts of the regular mesh from the geometry: the FE mesh (the upper block and, with an
// elastic lower solid, the lower block), the BI interface (its row 0) and the size estimates
// of a run all take them from here.
#pragma once

#include "solver/params.hpp"

#include <cmath>

namespace slipfront {

struct MeshSize {
  int nx; // nodes along x1 (periodic: width / dx elements, as many nodes)
  int ny; // nodes along x2: height / dx elements + 1 (+ the layer's rows, below)
  double dx;
  double height;      // of the elastic region, without the layer
  int layer_rows = 0; // top_boundary "pml": the rows of the layer above the height
};

// Height for "auto" of a block of P-wave speed c_p: the smallest h with 2 h / c_p >= duration
// (a P wave reflected by the far boundary cannot reach the interface before the run ends), in
// whole elements, plus one element.
inline double auto_height(const SimulationParams& p, double c_p) {
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  const double h = 0.5 * c_p * p.time.duration;
  return (std::ceil(h / dx - 1e-9) + 1.0) * dx;
}

inline MeshSize block_mesh_size(const SimulationParams& p, double height) {
  const double dx = 1.0 / p.geometry.nodes_per_meter;
  MeshSize m;
  m.dx = dx;
  m.nx = int(std::lround(p.geometry.width / dx));
  m.ny = int(std::lround(height / dx)) + 1;
  m.height = (m.ny - 1) * dx;
  return m;
}

// The upper block (x2 >= 0), with its perfectly matched layer above the height, if any.
inline MeshSize mesh_size(const SimulationParams& p) {
  const Geometry& g = p.geometry;
  MeshSize m =
      block_mesh_size(p, g.auto_height ? auto_height(p, p.material.p_wave_speed()) : g.height);
  if (p.top == TopBoundary::pml) {
    m.layer_rows = g.pml_elements;
    m.ny += g.pml_elements;
  }
  return m;
}

// The lower block (x2 <= 0) of an elastic lower solid (params.lower).
inline MeshSize lower_mesh_size(const SimulationParams& p) {
  const LowerSolid& l = p.lower;
  return block_mesh_size(p, l.auto_height ? auto_height(p, l.material.p_wave_speed()) : l.height);
}

} // namespace slipfront
