// The split-node interface law (solver/interface/split_node.hpp).
#include "solver/interface/split_node.hpp"

namespace slipfront {

namespace {

// Series combination of the two masses: the mass the relative motion has.
double effective_mass(double upper, double lower) {
  return upper * lower / (upper + lower);
}

} // namespace

SplitNodeStep resolve_split_node(const InterfaceNodeConstants& c, double gap,
                                 const InterfaceSide& upper, const InterfaceSide& lower,
                                 bool lower_rigid, double slip_speed, double strength,
                                 double previous_pressure, const PairForce& internal) {
  SplitNodeStep out;
  out.upper = upper;
  out.lower = lower;
  if (lower_rigid) { // the paper's plane: the single-node law on the upper node
    InterfaceNodeConstants rigid = c;
    rigid.mass1 = upper.mass1;
    rigid.mass2 = upper.mass2;
    out.relative = resolve_interface_node(rigid, gap, upper.v1, upper.v2, slip_speed, strength,
                                          previous_pressure);
    out.upper.v1 = out.relative.v1;
    out.upper.v2 = out.relative.v2;
    out.lower.v1 = out.lower.v2 = 0.0;
    return out;
  }

  // 1. The relative motion under the single-node law with the effective masses; the internal
  //    pair force -F (the perturbation's share of C - F) moves the sides apart by dt F / m_eff.
  InterfaceNodeConstants pair = c;
  pair.mass1 = effective_mass(upper.mass1, lower.mass1);
  pair.mass2 = effective_mass(upper.mass2, lower.mass2);
  const double rel1 = (upper.v1 - lower.v1) - c.dt * internal.f1 / pair.mass1;
  const double rel2 = (upper.v2 - lower.v2) - c.dt * internal.f2 / pair.mass2;
  const InterfaceNodeStep& r = out.relative =
      resolve_interface_node(pair, gap, rel1, rel2, slip_speed, strength, previous_pressure);
  const double force1 = r.contact_force1 - internal.f1; // C - F on the upper side

  // 2. Tangential: a stuck pair moves together at its centre-of-mass velocity (exactly one
  //    velocity); otherwise each side takes its share of the friction force (0 if open).
  const double total1 = upper.mass1 + lower.mass1;
  if (r.state == NodeState::stick) {
    const double common = (upper.mass1 * upper.v1 + lower.mass1 * lower.v1) / total1;
    out.upper.v1 = out.lower.v1 = common;
  } else {
    out.upper.v1 = upper.v1 + c.dt * force1 / upper.mass1;
    out.lower.v1 = lower.v1 - c.dt * force1 / lower.mass1;
  }

  // 3. Normal: in contact the gap closes (relative velocity r.v2 = -gap/dt), the pair's
  //    momentum kept; open, no force.
  if (r.state != NodeState::open) {
    const double total2 = upper.mass2 + lower.mass2;
    const double centre = (upper.mass2 * upper.v2 + lower.mass2 * lower.v2) / total2;
    out.upper.v2 = centre + lower.mass2 / total2 * r.v2;
    out.lower.v2 = centre - upper.mass2 / total2 * r.v2;
  } else { // C2 = 0: only -F2 acts
    const double force2 = r.contact_force2 - internal.f2;
    out.upper.v2 = upper.v2 + c.dt * force2 / upper.mass2;
    out.lower.v2 = lower.v2 - c.dt * force2 / lower.mass2;
  }
  return out;
}

} // namespace slipfront
