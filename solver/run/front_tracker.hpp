// Follows the slip front: per node, the first time the half-step slip speed crossed the
// threshold, interpolated linearly between the two half steps around the crossing.
#pragma once

#include <limits>
#include <vector>

namespace slipfront {

class FrontTracker {
public:
  FrontTracker(int nx, double threshold);

  // half_velocity holds v^{n+1/2}; the tracker keeps v^{n-1/2}. t_half = t_{n+1/2}.
  void update(const std::vector<double>& half_velocity, double t_half, double dt);
  const std::vector<double>& arrival() const { return arrival_; } // NaN where never reached
  double last_new_arrival() const { return last_new_arrival_; }   // -inf before any arrival

private:
  double threshold_;
  std::vector<double> arrival_, previous_;
  double last_new_arrival_ = -std::numeric_limits<double>::infinity();
};

} // namespace slipfront
