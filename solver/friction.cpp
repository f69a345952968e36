#include "solver/friction.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront {

double advance_strength(const Friction& friction, double strength, double pressure,
                        double slip_speed, double dt) {
  const double coulomb = friction.mu * std::max(0.0, pressure);
  if (friction.law == FrictionLaw::coulomb) return coulomb;
  const double rate = (slip_speed + friction.v_star) / friction.L;
  if (friction.update == StrengthUpdate::explicit_euler)
    return strength - dt * rate * (strength - coulomb);
  return coulomb + (strength - coulomb) * std::exp(-dt * rate);
}

} // namespace slipfront
