#include "solver/interface/friction.hpp"

#include "solver/interface/prakash_clifton.hpp"

#include <algorithm>

namespace slipfront {

double advance_strength(const Friction& friction, double strength, double pressure_start,
                        double pressure_end, double slip_speed, double dt) {
  switch (friction.law) {
  case FrictionLaw::coulomb:
    return friction.mu * std::max(0.0, pressure_end);
  case FrictionLaw::prakash_clifton:
    break;
  }
  return prakash_clifton_strength(friction, strength, pressure_start, pressure_end, slip_speed, dt);
}

} // namespace slipfront
