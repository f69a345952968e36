// Follows the slip front: per node, the first time the half-step slip speed crossed the
// threshold, interpolated linearly between the two half steps around the crossing; and the
// first time the front reached a node outside the nucleation patch (the arrest rule's start
// for an overstressed patch).
#pragma once

#include <limits>
#include <vector>

namespace slipfront {

class FrontTracker {
public:
  // `in_patch`: the nodes of the nucleation patch (empty: none).
  FrontTracker(int nx, double threshold, std::vector<bool> in_patch = {});

  // half_velocity holds v^{n+1/2}; the tracker keeps v^{n-1/2}. t_half = t_{n+1/2}.
  void update(const std::vector<double>& half_velocity, double t_half, double dt);
  const std::vector<double>& arrival() const { return arrival_; } // NaN where never reached
  double last_new_arrival() const { return last_new_arrival_; }   // -inf before any arrival
  // The first arrival at a node outside the patch; +inf before one.
  double first_arrival_outside() const { return first_arrival_outside_; }

private:
  double threshold_;
  std::vector<double> arrival_, previous_;
  std::vector<bool> in_patch_;
  double last_new_arrival_ = -std::numeric_limits<double>::infinity();
  double first_arrival_outside_ = std::numeric_limits<double>::infinity();
};

} // namespace slipfront
