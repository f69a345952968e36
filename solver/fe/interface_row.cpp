// The interface row of the FE step (solver/fe/mesh_stepper.hpp), where the contact and
// friction law of the plane acts (paper eq. 1-3; docs/physics.md "The step at an interface
// node"). The block has K u of the row (ElasticBlock::begin_interface_row); this writes the
// row's velocities, the interface fields of the step and its energy terms.
#include "solver/fe/mesh_stepper.hpp"
#include "solver/interface/nucleation.hpp"

#include <cmath>

namespace slipfront::fe {

void MeshStepper::interface_row(LevelRecord& level) {
  const int nx = upper_.nx();
  const double dx = upper_.dx();
  // Load changes at the interface at t_n: nucleation (tensile) and any extra traction.
  const double t = level.time;
  for (int i = 0; i < nx; ++i) {
    const double x1 = iface_.x1[i];
    InterfaceTraction extra;
    if (params_.extra_load) extra = params_.extra_load(x1, t);
    const double nucleation =
        nucleation_traction(params_.nucleation, params_.loading.normal_stress, x1, t);
    load1_[i] = extra.t1 * dx;
    load2_[i] = (nucleation + extra.t2) * dx;
  }
  const bool compute_energy = level.compute_energy;
  // The initial contact force of the plane, C0 = dx (-tau1_0, |tau2_0|); the perturbation
  // sees C - C0.
  const double c0_1 = -params_.loading.shear_stress * dx;
  const double c0_2 = std::abs(params_.loading.normal_stress) * dx;
  const double m = upper_.node_mass(0);
  double* vx = upper_.velocity().x.row(0);
  double* vy = upper_.velocity().y.row(0);
  const double* ux = upper_.displacement().x.row(0);
  const double* uy = upper_.displacement().y.row(0);
  const double* kx0 = upper_.interface_stiffness_x();
  const double* ky0 = upper_.interface_stiffness_y();
  const bool damped = upper_.damped();
  const double* kdx = upper_.interface_damping_x();
  const double* kdy = upper_.interface_damping_y();
  double work = 0, dissipated = 0, kinetic = 0, strain = 0;
  for (int i = 0; i < nx; ++i) {
    double f1 = -kx0[i] + load1_[i] - c0_1; // every force but the plane's
    double f2 = -ky0[i] + load2_[i] - c0_2;
    if (damped) { // the damping force -a K v^{n-1/2}
      f1 -= kdx[i];
      f2 -= kdy[i];
    }
    const double v1_old = vx[i], v2_old = vy[i];
    // The trial (free) velocities of the next half step; the slip speed over the last
    // interval is that of the last half step.
    const double v1_trial = v1_old + dt_ * f1 / m;
    const double v2_trial = v2_old + dt_ * f2 / m;
    const InterfaceNodeStep r = resolve_interface_node(
        node_, uy[i], v1_trial, v2_trial, std::abs(v1_old), iface_.strength[i], iface_.pressure[i]);
    const double v1_new = r.v1, v2_new = r.v2;
    vx[i] = v1_new;
    vy[i] = v2_new;

    const double v1_mid = 0.5 * (v1_old + v1_new), v2_mid = 0.5 * (v2_old + v2_new);
    iface_.velocity[i] = v1_mid;
    iface_.half_velocity[i] = v1_new;
    iface_.slip[i] = ux[i];
    iface_.opening[i] = uy[i];
    iface_.shear_traction[i] = -r.contact_force1 / dx;
    iface_.pressure[i] = r.pressure;
    iface_.strength[i] = r.strength;
    iface_.state[i] = std::int8_t(r.state);

    // Work over the step: F^n . (u^{n+1} - u^{n-1}) / 2 = F^n . dt (v^{n+1/2} + v^{n-1/2}) / 2.
    work += dt_ * ((load1_[i] - c0_1) * v1_mid + (load2_[i] - c0_2) * v2_mid);
    dissipated -= dt_ * (r.contact_force1 * v1_mid + r.contact_force2 * v2_mid);
    if (damped) dissipated += dt_ * (kdx[i] * v1_mid + kdy[i] * v2_mid);
    if (compute_energy) {
      kinetic += v1_new * v1_new + v2_new * v2_new;
      strain += kx0[i] * (ux[i] + dt_ * v1_new) + ky0[i] * (uy[i] + dt_ * v2_new);
    }
  }
  level.work = work;
  level.upper.row_dissipated[0] = dissipated;
  if (compute_energy) {
    level.upper.row_kinetic[0] = 0.5 * m * kinetic;
    level.upper.row_strain[0] = 0.5 * strain;
  }
}

} // namespace slipfront::fe
