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

// One directional part of it, K_aa = ∫ B_a^T D B_a, where B_a keeps only the derivatives
// along x_a (the stretched-coordinate split of the perfectly matched layer,
// solver/fe/absorbing_layer.hpp): along_x1 is K_11, along_x2 is K_22; both is K.
enum class StrainPart { both, along_x1, along_x2 };
ElementStiffness q4_plane_strain_stiffness_part(const Material& material, StrainPart part);

} // namespace slipfront::fe
