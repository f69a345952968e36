#include "api/length_fit/law_model.hpp"

#include "solver/interface/friction/strength_law.hpp"

#include <cmath>

namespace slipfront::api {

std::vector<double> prakash_clifton_strength(const InterfaceRecord& record,
                                             const LawParameters& law) {
  Friction friction;
  friction.law = "prakash_clifton"; // paper eq. 1, the law of the procedure of paper §6
  friction.update = StrengthUpdate::exponential_ramp;
  friction.mu = law.mu;
  friction.L = law.L;
  friction.v_star = law.v_star;
  const StrengthLaw strength_law(friction);
  const std::size_t n = record.size();
  std::vector<double> strength(n);
  if (n == 0) return strength;
  FrictionState state = strength_law.resting_state(friction, record.contact_pressure[0]);
  strength[0] = strength_law.strength(friction, state);
  for (std::size_t k = 1; k < n; ++k) {
    const double dt = record.time[k] - record.time[k - 1];
    const double speed = 0.5 * (std::abs(record.slip_rate[k - 1]) + std::abs(record.slip_rate[k]));
    const FrictionStep step = strength_law.advance(friction, state, record.contact_pressure[k - 1],
                                                   record.contact_pressure[k], speed, dt);
    state = step.state;
    strength[k] = step.strength;
  }
  return strength;
}

} // namespace slipfront::api
