// Stiffness of one square, bilinear (Q4) plane-strain element, integrated with 2x2 Gauss
// points (Hughes, The Finite Element Method, ch. 3; Zienkiewicz & Taylor vol. 1, ch. 6).
//
// Local nodes are numbered counter-clockwise from the lower-left corner:
//   3 (0,h) --- 2 (h,h)
//   |           |
//   0 (0,0) --- 1 (h,0)
// and degrees of freedom are ordered (u1, u2) per node: K[2a + i][2b + k].
// For a square element in 2D the stiffness does not depend on the element size.
#pragma once

#include "solver/params.hpp"

#include <array>

namespace slipfront::fe {

using ElementStiffness = std::array<std::array<double, 8>, 8>;

// Offsets (column, row) of the local nodes from the element's lower-left node.
inline constexpr std::array<std::array<int, 2>, 4> kQ4NodeOffset = {
    {{0, 0}, {1, 0}, {1, 1}, {0, 1}}};

ElementStiffness q4_plane_strain_stiffness(const Material& material);

} // namespace slipfront::fe
