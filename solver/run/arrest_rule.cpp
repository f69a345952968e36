#include "solver/run/arrest_rule.hpp"

#include "solver/interface/nucleation.hpp"

#include <algorithm>

namespace slipfront {

ArrestRule::ArrestRule(const SimulationParams& params)
    : quiet_after_(nucleation_end_time(params.nucleation)), patch_(params.nucleation.patch()),
      window_(params.time.arrest_window), stop_on_arrest_(params.time.stop_on_arrest) {}

bool ArrestRule::update(double t_n, double last_new_arrival, double first_arrival_outside) {
  const double nucleated = patch_ ? std::max(quiet_after_, first_arrival_outside) : quiet_after_;
  const double quiet_since = std::max(nucleated, last_new_arrival);
  arrested_ = t_n - quiet_since >= window_;
  return arrested_ && stop_on_arrest_;
}

} // namespace slipfront
