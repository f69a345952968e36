// The two boundary rows of the FE step (solver/fe/mesh_stepper.hpp): the interface row, where
// the contact and friction law of the plane acts (paper eq. 1-3;
// docs/physics.md "The step at an interface node"), and the absorbing top with its
// Lysmer-Kuhlemeyer dashpots. Each gets K u of its row from the caller and writes its
// velocities and its energy terms for the step's record.
#include "solver/fe/mesh_stepper.hpp"
#include "solver/interface/nucleation.hpp"

#include <cmath>

namespace slipfront::fe {

void MeshStepper::interface_row(LevelRecord& level) {
  // Load changes at the interface at t_n: nucleation (tensile) and any extra traction.
  const double t = level.time;
  for (int i = 0; i < nx_; ++i) {
    const double x1 = iface_.x1[i];
    InterfaceTraction extra;
    if (params_.extra_load) extra = params_.extra_load(x1, t);
    const double nucleation =
        nucleation_traction(params_.nucleation, parameters_.normal_stress[i], x1, t);
    load1_[i] = extra.t1 * dx_;
    load2_[i] = (nucleation + extra.t2) * dx_;
  }
  const bool compute_energy = level.compute_energy;
  const double m = node_mass(0);
  double* vx = v_.x.row(0);
  double* vy = v_.y.row(0);
  const double* ux = u_.x.row(0);
  const double* uy = u_.y.row(0);
  const bool damped = damping_a_ > 0;
  double work = 0, dissipated = 0, kinetic = 0, strain = 0;
  for (int i = 0; i < nx_; ++i) {
    // The initial contact force of the plane, C0 = dx (-tau0_i, |sigma0_i|); the
    // perturbation sees C - C0.
    const double c0_1 = -parameters_.shear_stress[i] * dx_;
    const double c0_2 = std::abs(parameters_.normal_stress[i]) * dx_;
    double f1 = -kx0_[i] + load1_[i] - c0_1; // every force but the plane's
    double f2 = -ky0_[i] + load2_[i] - c0_2;
    if (damped) { // the damping force -a K v^{n-1/2}
      f1 -= kdx_[i];
      f2 -= kdy_[i];
    }
    const double v1_old = vx[i], v2_old = vy[i];
    // The trial (free) velocities of the next half step; the slip speed over the last
    // interval is that of the last half step.
    const double v1_trial = v1_old + dt_ * f1 / m;
    const double v2_trial = v2_old + dt_ * f2 / m;
    const InterfaceNodeStep r =
        resolve_interface_node(node_, parameters_.friction[i], uy[i], v1_trial, v2_trial,
                               std::abs(v1_old), friction_[i], iface_.pressure[i]);
    friction_[i] = r.friction;
    const double v1_new = r.v1, v2_new = r.v2;
    vx[i] = v1_new;
    vy[i] = v2_new;

    const double v1_mid = 0.5 * (v1_old + v1_new), v2_mid = 0.5 * (v2_old + v2_new);
    iface_.velocity[i] = v1_mid;
    iface_.half_velocity[i] = v1_new;
    iface_.slip[i] = ux[i];
    iface_.opening[i] = uy[i];
    iface_.shear_traction[i] = -r.contact_force1 / dx_;
    iface_.pressure[i] = r.pressure;
    iface_.strength[i] = r.strength;
    iface_.state[i] = std::int8_t(r.state);

    // Work over the step: F^n . (u^{n+1} - u^{n-1}) / 2 = F^n . dt (v^{n+1/2} + v^{n-1/2}) / 2.
    work += dt_ * ((load1_[i] - c0_1) * v1_mid + (load2_[i] - c0_2) * v2_mid);
    dissipated -= dt_ * (r.contact_force1 * v1_mid + r.contact_force2 * v2_mid);
    if (damped) dissipated += dt_ * (kdx_[i] * v1_mid + kdy_[i] * v2_mid);
    if (compute_energy) {
      kinetic += v1_new * v1_new + v2_new * v2_new;
      strain += kx0_[i] * (ux[i] + dt_ * v1_new) + ky0_[i] * (uy[i] + dt_ * v2_new);
    }
  }
  level.work = work;
  level.row_dissipated[0] = dissipated;
  if (compute_energy) {
    level.row_kinetic[0] = 0.5 * m * kinetic;
    level.row_strain[0] = 0.5 * strain;
  }
}

void MeshStepper::absorbing_top_row(LevelRecord& level, const double* uxm, const double* uym) {
  const bool compute_energy = level.compute_energy;
  // Lysmer-Kuhlemeyer dashpots on the top nodes: force -c v with c = rho c_s dx (tangential)
  // and rho c_p dx (normal). Taken at the step's mid velocity (v^{n+1/2} + v^{n-1/2})/2,
  // which is implicit in v^{n+1/2} but diagonal:
  //   v^{n+1/2} (1 + a) = v^{n-1/2} (1 - a) - dt/m (K u)^n,  a = c dt / (2 m).
  const int j = ny_ - 1;
  const double m = node_mass(j);
  const double rho = params_.material.density;
  const double c_x = rho * params_.material.s_wave_speed() * dx_;
  const double c_y = rho * params_.material.p_wave_speed() * dx_;
  const double a_x = c_x * dt_ / (2 * m), a_y = c_y * dt_ / (2 * m);
  double* vx = v_.x.row(j);
  double* vy = v_.y.row(j);
  const double* ux0 = u_.x.row(j);
  const double* uy0 = u_.y.row(j);
  const double* z = zero_row_.data() + 1;
  const bool damped = damping_a_ > 0; // then kdx_top_, kdy_top_ hold the row's damping force
  double dissipated = 0, kinetic = 0, strain = 0;
  for_each_node_force(
      stencils_.top, uxm, uym, ux0, uy0, z, z, nx_, [&](int i, double kx, double ky) {
        const double fx = damped ? kx + kdx_top_[i] : kx, fy = damped ? ky + kdy_top_[i] : ky;
        const double vx_new = (vx[i] * (1 - a_x) - dt_ / m * fx) / (1 + a_x);
        const double vy_new = (vy[i] * (1 - a_y) - dt_ / m * fy) / (1 + a_y);
        const double vx_mid = 0.5 * (vx[i] + vx_new), vy_mid = 0.5 * (vy[i] + vy_new);
        dissipated += dt_ * (c_x * vx_mid * vx_mid + c_y * vy_mid * vy_mid);
        if (damped) dissipated += dt_ * (kdx_top_[i] * vx_mid + kdy_top_[i] * vy_mid);
        vx[i] = vx_new;
        vy[i] = vy_new;
        if (compute_energy) {
          kinetic += vx_new * vx_new + vy_new * vy_new;
          strain += kx * (ux0[i] + dt_ * vx_new) + ky * (uy0[i] + dt_ * vy_new);
        }
      });
  level.row_dissipated[j] = dissipated;
  if (compute_energy) {
    level.row_kinetic[j] = 0.5 * m * kinetic;
    level.row_strain[j] = 0.5 * strain;
  }
}

} // namespace slipfront::fe
