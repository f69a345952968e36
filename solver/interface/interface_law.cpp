#include "solver/interface/interface_law.hpp"

#include <cmath>

namespace slipfront {

InterfaceNodeStep resolve_interface_node(const InterfaceNodeConstants& c,
                                         const FrictionValues& friction, double u2, double v1_trial,
                                         double v2_trial, double slip_speed,
                                         const FrictionState& state, double previous_pressure) {
  InterfaceNodeStep out;
  // 1. Next normal displacement of the trial (free) motion.
  const double u2_trial = u2 + c.dt * v2_trial;

  // 2. Normal reaction that closes the gap exactly: u2_next = u2_trial + dt^2 R / m2 = 0.
  const double reaction = -c.mass2 * u2_trial / (c.dt * c.dt);
  const bool in_contact = reaction > 0.0;
  out.contact_force2 = in_contact ? reaction : 0.0;
  out.pressure = out.contact_force2 / c.tributary_length;

  // 3. Strength over the step from the last one to this one: the pressure goes from the
  //    last step's to this step's, the slip speed is that of the last interval (FE: the
  //    last half step's, the velocity over that interval in the leapfrog scheme).
  //    (The strength itself is asked for below, where the node's state needs it.)
  out.friction =
      c.law.advance_state(friction, state, previous_pressure, out.pressure, slip_speed, c.dt);

  // 4. Tangential: stick if the plane can hold the node, else slip at strength.
  // The constrained velocities are set exactly (not through the force, whose round-off
  // would leave 1e-20 m/s of noise on a stuck, closed node).
  out.v2 = in_contact ? -u2 / c.dt : v2_trial; // in contact: u2_next = u2 + dt v2 = 0
  if (!in_contact) {
    out.strength = c.law.strength(friction, out.friction, slip_speed);
    out.state = NodeState::open;
    out.contact_force1 = 0.0;
    out.v1 = v1_trial;
    return out;
  }
  if (c.law.coefficient().rate_dependent()) {
    // A law of the slip rate has no stick state: the traction is the strength at the slip
    // rate it lets through, tau_lock - eta V = sigma* mu(|V|, state) sign V, with the
    // node's impedance eta = m1 / (dt dx) and tau_lock = eta v1_trial the traction that
    // would hold it (docs/physics.md "Rate-and-state friction").
    const double eta = c.mass1 / (c.dt * c.tributary_length);
    const double tau_lock = eta * v1_trial;
    const double v = c.law.coefficient().solve_slip_rate(
        friction, out.friction, c.law.normal_stress_seen(friction, out.friction), eta, tau_lock,
        slip_speed);
    out.state = NodeState::slip;
    out.v1 = v;
    const double traction = tau_lock - eta * v;
    out.contact_force1 = -traction * c.tributary_length;
    out.strength = std::abs(traction); // the strength at V, to the solve's tolerance
    return out;
  }
  out.strength = c.law.strength(friction, out.friction, slip_speed);
  const double stick_force = -c.mass1 * v1_trial / c.dt; // makes v1 = v1_trial + dt F/m1 = 0
  const double limit = out.strength * c.tributary_length;
  if (std::abs(stick_force) <= limit) {
    out.state = NodeState::stick;
    out.contact_force1 = stick_force;
    out.v1 = 0.0;
  } else {
    out.state = NodeState::slip;
    out.contact_force1 = v1_trial > 0.0 ? -limit : limit;
    out.v1 = v1_trial + c.dt * out.contact_force1 / c.mass1;
  }
  return out;
}

} // namespace slipfront
