// A scalar field on the nodes of the regular mesh, periodic in x1.
//
// Row-major with x1 fastest. Each row carries one ghost node on each side (index -1 and
// nx) holding copies of the periodic neighbours, so that the stencil loop over a row has
// no wrap-around branch. Row j is the line x2 = j * dx; row 0 is the interface.
#pragma once

#include <cstddef>
#include <vector>

namespace slipfront::fe {

class NodalField {
public:
  NodalField() = default;
  NodalField(int nx, int ny)
      : nx_(nx), ny_(ny), stride_(nx + 2), data_(std::size_t(nx + 2) * ny, 0.0) {}

  int nx() const { return nx_; }
  int ny() const { return ny_; }

  // Pointer to node (0, j); valid indices are -1 .. nx.
  double* row(int j) { return data_.data() + std::size_t(j) * stride_ + 1; }
  const double* row(int j) const { return data_.data() + std::size_t(j) * stride_ + 1; }

  double& at(int i, int j) { return row(j)[i]; }
  double at(int i, int j) const { return row(j)[i]; }

  // Copy the periodic neighbours into the ghost nodes of row j.
  void refresh_ghosts(int j) {
    double* r = row(j);
    r[-1] = r[nx_ - 1];
    r[nx_] = r[0];
  }
  void refresh_all_ghosts() {
    for (int j = 0; j < ny_; ++j)
      refresh_ghosts(j);
  }

private:
  int nx_ = 0, ny_ = 0, stride_ = 0;
  std::vector<double> data_;
};

// A 2D vector field (components along x1 and x2).
struct VectorField {
  NodalField x, y;
  VectorField() = default;
  VectorField(int nx, int ny) : x(nx, ny), y(nx, ny) {}
};

} // namespace slipfront::fe
