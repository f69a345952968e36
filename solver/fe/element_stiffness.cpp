#include "solver/fe/element_stiffness.hpp"

#include <cmath>

namespace slipfront::fe {

ElementStiffness q4_plane_strain_stiffness(const Material& material) {
  return q4_plane_strain_stiffness_part(material, StrainPart::both);
}

ElementStiffness q4_plane_strain_stiffness_part(const Material& material, StrainPart part) {
  const bool with_d1 = part != StrainPart::along_x2, with_d2 = part != StrainPart::along_x1;
  // Plane-strain elasticity matrix D (Voigt order xx, yy, xy with engineering shear).
  const double lambda = material.lame_lambda();
  const double mu = material.shear_modulus();
  const double D[3][3] = {{lambda + 2 * mu, lambda, 0}, {lambda, lambda + 2 * mu, 0}, {0, 0, mu}};

  // Reference square [-1,1]^2 mapped onto [0,h]^2: dN/dx = (2/h) dN/dxi, detJ = h^2/4.
  // The h factors cancel in B^T D B detJ, so take h = 2 (dN/dx = dN/dxi, detJ = 1).
  const double xi_a[4] = {-1, 1, 1, -1};
  const double eta_a[4] = {-1, -1, 1, 1};
  const double g = 1.0 / std::sqrt(3.0); // 2-point Gauss abscissa, weight 1

  ElementStiffness K{};
  for (double xi : {-g, g}) {
    for (double eta : {-g, g}) {
      double B[3][8] = {};
      for (int a = 0; a < 4; ++a) {
        const double dN_dx = with_d1 ? 0.25 * xi_a[a] * (1 + eta_a[a] * eta) : 0.0;
        const double dN_dy = with_d2 ? 0.25 * eta_a[a] * (1 + xi_a[a] * xi) : 0.0;
        B[0][2 * a] = dN_dx;     // eps_xx
        B[1][2 * a + 1] = dN_dy; // eps_yy
        B[2][2 * a] = dN_dy;     // gamma_xy
        B[2][2 * a + 1] = dN_dx;
      }
      for (int r = 0; r < 8; ++r)
        for (int c = 0; c < 8; ++c) {
          double sum = 0;
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q)
              sum += B[p][r] * D[p][q] * B[q][c];
          K[r][c] += sum;
        }
    }
  }
  return K;
}

} // namespace slipfront::fe
