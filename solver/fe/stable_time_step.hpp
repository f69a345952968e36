// The stable time step of central differences for the discrete system:
//   dt_stable = 2 / omega_max,  omega_max^2 = largest eigenvalue of M^-1 K
// (Hughes, The Finite Element Method, sec. 9.3). omega_max^2 is found by power iteration
// on the symmetric M^-1/2 K M^-1/2 of the free block (periodic in x1, free top and bottom):
// contact and stick only remove degrees of freedom, which cannot raise the largest
// eigenvalue (Cauchy interlacing), so the free block bounds every contact state.
#pragma once

#include "solver/fe/stencil.hpp"

namespace slipfront::fe {

struct EigenEstimate {
  double lambda_max = 0; // omega_max^2 [1/s^2]
  int iterations = 0;
  double relative_change = 0; // of the Rayleigh quotient at the last iteration
};

// Power iteration on the nx x ny free block with element size dx and density rho. The
// Rayleigh quotient approaches omega_max^2 from below; at the default tolerance (relative
// change per iteration) it is within about 1e-11 of it on the 24 x 24 patch (~30 ms).
EigenEstimate largest_eigenvalue(const MeshStencils& stencils, int nx, int ny, double dx,
                                 double density, int max_iterations = 20000,
                                 double tolerance = 1e-13);

// The stable step of the mesh nx x ny. The highest modes of a regular mesh are local
// (checkerboard-like), so the iteration runs on a patch of at most 24 x 24 nodes with the
// same boundaries (an even number of columns, which holds the shortest periodic wave).
double stable_time_step(const MeshStencils& stencils, int nx, int ny, double dx, double density);

// The stable step with a stiffness-proportional damping force -a K v taken at the last half
// step's velocity v^{n-1/2} (solver/fe/mesh_stepper.hpp). Mode by mode (C = a K shares the
// modes of M^-1 K) the recursion u^{n+1} = (2 - a w^2 dt - w^2 dt^2) u^n - (1 - a w^2 dt)
// u^{n-1} is stable iff w^2 (dt^2 + 2 a dt) < 4, i.e.
//   dt < sqrt(a^2 + dt0^2) - a = dt0 (sqrt(1 + xi^2) - xi),  dt0 = 2 / w,  xi = a w / 2,
// which decreases with w, so the highest mode (dt0 = the undamped stable step) rules.
// a = 0 gives dt0 back exactly.
double damped_stable_time_step(double undamped_dt, double a);

} // namespace slipfront::fe
