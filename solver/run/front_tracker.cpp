#include "solver/run/front_tracker.hpp"

#include <algorithm>
#include <cmath>

namespace slipfront {

FrontTracker::FrontTracker(int nx, double threshold, std::vector<bool> in_patch)
    : threshold_(threshold), arrival_(nx, std::numeric_limits<double>::quiet_NaN()),
      previous_(nx, 0.0), in_patch_(std::move(in_patch)) {
  in_patch_.resize(arrival_.size(), false);
}

void FrontTracker::update(const std::vector<double>& half_velocity, double t_half, double dt) {
  for (std::size_t i = 0; i < arrival_.size(); ++i) {
    const double now = std::abs(half_velocity[i]);
    if (std::isnan(arrival_[i]) && now > threshold_) {
      const double before = std::abs(previous_[i]);
      const double s = (threshold_ - before) / (now - before); // in [0, 1)
      // Not before t = 0: the motion starts at t_0 even though v^{-1/2} sits at -dt/2.
      arrival_[i] = std::max(0.0, t_half - dt + std::clamp(s, 0.0, 1.0) * dt);
      last_new_arrival_ = std::max(last_new_arrival_, arrival_[i]);
      if (!in_patch_[i]) first_arrival_outside_ = std::min(first_arrival_outside_, arrival_[i]);
    }
    previous_[i] = half_velocity[i];
  }
}

} // namespace slipfront
