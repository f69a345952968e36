// The interface row of the FE step (solver/fe/mesh_stepper.hpp), where the contact and
// friction law acts (paper eq. 1-3; docs/physics.md "The step at an interface node", "Two
// solids"): on the rigid plane the single-node law, between two solids the split-node law
// (Andrews 1999; Day et al. 2005), both through resolve_split_node. The blocks have K u of
// their row 0 (ElasticBlock::begin_interface_row); this writes the rows' velocities, the
// interface fields of the step and its energy terms.
#include "solver/fe/mesh_stepper.hpp"
#include "solver/interface/nucleation.hpp"
#include "solver/interface/split_node.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront::fe {

namespace {

// Row 0 of a block as the interface row reads and writes it, in the block's own frame.
struct InterfaceRowOf {
  double* vx;
  double* vy;
  const double* ux;
  const double* uy;
  const double* kx; // K u
  const double* ky;
  const double* kdx; // the damping force a K v^{n-1/2} (damped blocks)
  const double* kdy;
  double mass;
  bool damped;
};

InterfaceRowOf interface_row_of(ElasticBlock& block) {
  return {block.velocity().x.row(0),
          block.velocity().y.row(0),
          block.displacement().x.row(0),
          block.displacement().y.row(0),
          block.interface_stiffness_x(),
          block.interface_stiffness_y(),
          block.interface_damping_x(),
          block.interface_damping_y(),
          block.node_mass(0),
          block.damped()};
}

} // namespace

void MeshStepper::interface_row(LevelRecord& level) {
  const int nx = upper_.nx();
  const double dx = upper_.dx();
  // Load changes at the interface at t_n: nucleation (tensile) and any extra traction, +L on
  // the upper solid, -L on the lower.
  const double t = level.time;
  for (int i = 0; i < nx; ++i) {
    const double x1 = iface_.x1[i];
    InterfaceTraction extra;
    if (params_.extra_load) extra = params_.extra_load(x1, t);
    const double nucleation =
        nucleation_traction(params_.nucleation, parameters_.normal_stress[i], x1, t);
    load1_[i] = (extra.t1 + nucleation_shear_traction(params_.nucleation, x1, t)) * dx;
    load2_[i] = (nucleation + extra.t2) * dx;
  }
  const bool compute_energy = level.compute_energy;
  const InterfaceRowOf up = interface_row_of(upper_);
  // The lower block's row in its mirrored frame (u'_2 = -u_2, F'_2 = -F_2); unused when rigid.
  const bool two_solids = lower_.has_value();
  const InterfaceRowOf lo = two_solids ? interface_row_of(*lower_) : InterfaceRowOf{};
  double work = 0, dissipated = 0, kinetic = 0, strain = 0;
  double lower_dissipated = 0, lower_kinetic = 0, lower_strain = 0;
  const bool rate_dependent = node_.law.coefficient().rate_dependent();
  for (int i = 0; i < nx; ++i) {
    // The initial contact force on the upper solid, C0_i = dx (-tau0_i, |sigma0_i|) (the
    // node's initial stresses); the perturbation sees C - C0 (the lower block -(C - C0)).
    const double c0_1 = -parameters_.shear_stress[i] * dx;
    const double c0_2 = std::abs(parameters_.normal_stress[i]) * dx;
    const PairForce c0{c0_1, c0_2};
    // Every force on the upper node but C; on the plane with -C0 (the plane takes C), between
    // two solids without (the pair's internal force C0, PairForce in split_node.hpp).
    double f1 = -up.kx[i] + load1_[i];
    double f2 = -up.ky[i] + load2_[i];
    if (!two_solids) {
      f1 -= c0_1;
      f2 -= c0_2;
    }
    if (up.damped) { // the damping force -a K v^{n-1/2}
      f1 -= up.kdx[i];
      f2 -= up.kdy[i];
    }
    const double v1_old = up.vx[i], v2_old = up.vy[i];
    // The trial (free) velocities of the next half step; the slip speed over the last
    // interval is that of the last half step.
    const InterfaceSide upper{up.mass, up.mass, v1_old + dt_ * f1 / up.mass,
                              v2_old + dt_ * f2 / up.mass};
    InterfaceSide lower;                  // true frame
    double gap = up.uy[i];                // u2(upper) - u2(lower)
    double slip_speed = std::abs(v1_old); // |V^{n-1/2}|
    double w1_old = 0, w2_old = 0;        // the lower node's v^{n-1/2}, mirrored
    if (two_solids) {                     // every force on the lower node but -(C - C0):
      double g1 = -lo.kx[i] - load1_[i];  //   -L1 along x1,
      double g2 = -lo.ky[i] + load2_[i];  //   (-1) (-L2) along y' = -x2
      if (lo.damped) {
        g1 -= lo.kdx[i];
        g2 -= lo.kdy[i];
      }
      w1_old = lo.vx[i];
      w2_old = lo.vy[i];
      lower = {lo.mass, lo.mass, w1_old + dt_ * g1 / lo.mass, -(w2_old + dt_ * g2 / lo.mass)};
      gap = up.uy[i] + lo.uy[i];
      slip_speed = std::abs(v1_old - w1_old);
    }
    // Before the first step the medium is at rest, but a law of the slip rate may have the
    // interface slide already (rate-and-state's initial slip rate): its state is advanced
    // over the first interval with that rate.
    if (t == 0.0)
      slip_speed =
          std::max(slip_speed, node_.law.coefficient().initial_slip_rate(parameters_.friction[i]));
    SplitNodeStep s =
        resolve_split_node(node_, parameters_.friction[i], gap, upper, lower, !two_solids,
                           slip_speed, friction_[i], iface_.pressure[i], c0);
    if (rate_dependent) {
      // A law of the slip rate is solved at V^{n+1/2}: its state is advanced to there too,
      // with the mean slip speed over [t_{n-1/2}, t_{n+1/2}] (a corrector, as the spectral
      // method's; docs/physics.md "Rate-and-state friction").
      const double mean_speed = 0.5 * (slip_speed + std::abs(s.relative.v1));
      s = resolve_split_node(node_, parameters_.friction[i], gap, upper, lower, !two_solids,
                             mean_speed, friction_[i], iface_.pressure[i], c0);
    }
    const InterfaceNodeStep& r = s.relative;
    friction_[i] = r.friction;
    const double v1_new = s.upper.v1, v2_new = s.upper.v2;
    up.vx[i] = v1_new;
    up.vy[i] = v2_new;
    const double v1_mid = 0.5 * (v1_old + v1_new), v2_mid = 0.5 * (v2_old + v2_new);

    // The relative motion (upper minus lower, true frame): the plane's is the upper node's.
    double rel1_mid = v1_mid, rel2_mid = v2_mid, rel1_new = v1_new;
    double slip = up.ux[i];
    if (two_solids) {
      const double w1_new = s.lower.v1, w2_new = -s.lower.v2; // mirrored
      lo.vx[i] = w1_new;
      lo.vy[i] = w2_new;
      const double w1_mid = 0.5 * (w1_old + w1_new), w2_mid = 0.5 * (w2_old + w2_new);
      rel1_mid = v1_mid - w1_mid;
      rel2_mid = v2_mid + w2_mid;
      rel1_new = v1_new - w1_new;
      slip = up.ux[i] - lo.ux[i];
      if (lo.damped) lower_dissipated += dt_ * (lo.kdx[i] * w1_mid + lo.kdy[i] * w2_mid);
      if (compute_energy) {
        lower_kinetic += w1_new * w1_new + w2_new * w2_new;
        lower_strain += lo.kx[i] * (lo.ux[i] + dt_ * w1_new) + lo.ky[i] * (lo.uy[i] + dt_ * w2_new);
      }
    }
    iface_.velocity[i] = rel1_mid;
    iface_.half_velocity[i] = rel1_new;
    iface_.slip[i] = slip;
    iface_.opening[i] = gap;
    iface_.shear_traction[i] = -r.contact_force1 / dx;
    iface_.pressure[i] = r.pressure;
    iface_.strength[i] = r.strength;
    iface_.state[i] = std::int8_t(r.state);

    // Work over the step: F^n . (u^{n+1} - u^{n-1}) / 2 = F^n . dt (v^{n+1/2} + v^{n-1/2}) / 2,
    // of the interface forces on the relative motion (+F on the upper node, -F on the lower).
    work += dt_ * ((load1_[i] - c0_1) * rel1_mid + (load2_[i] - c0_2) * rel2_mid);
    dissipated -= dt_ * (r.contact_force1 * rel1_mid + r.contact_force2 * rel2_mid);
    if (up.damped) dissipated += dt_ * (up.kdx[i] * v1_mid + up.kdy[i] * v2_mid);
    if (compute_energy) {
      kinetic += v1_new * v1_new + v2_new * v2_new;
      strain += up.kx[i] * (up.ux[i] + dt_ * v1_new) + up.ky[i] * (up.uy[i] + dt_ * v2_new);
    }
  }
  level.work = work;
  level.upper.row_dissipated[0] = dissipated;
  if (compute_energy) {
    level.upper.row_kinetic[0] = 0.5 * up.mass * kinetic;
    level.upper.row_strain[0] = 0.5 * strain;
  }
  if (!two_solids) return;
  level.lower.row_dissipated[0] = lower_dissipated;
  if (compute_energy) {
    level.lower.row_kinetic[0] = 0.5 * lo.mass * lower_kinetic;
    level.lower.row_strain[0] = 0.5 * lower_strain;
  }
}

} // namespace slipfront::fe
