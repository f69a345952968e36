// What a rupture method actually ran: its discretisation and time step.
#pragma once

#include "solver/params.hpp"

namespace slipfront {

// The discrete system that was actually run.
struct MeshInfo {
  int nx = 0; // nodes along x1 (periodic: no duplicate node)
  int ny = 0; // nodes along x2, including interface and top
  double dx = 0.0;
  double height = 0.0; // after "auto" resolution
  double stable_dt = 0.0;
  double dt = 0.0;
  int threads = 1;
  Method method = Method::finite_element; // spectral_bi: ny = 1 (the interface), no height
  // FE with an elastic lower solid: its block's rows and height (after "auto"); else 0.
  int lower_ny = 0;
  double lower_height = 0.0;
};

} // namespace slipfront
