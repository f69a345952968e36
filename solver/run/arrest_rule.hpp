// The arrest rule (docs/metrics.md): the rupture has arrested once, after the nucleation
// has ended, no node has been newly reached by the front for time.arrest_window.
#pragma once

#include "solver/params.hpp"

namespace slipfront {

class ArrestRule {
public:
  explicit ArrestRule(const SimulationParams& params);

  // After step n: last_new_arrival is the latest front arrival time (-inf if none).
  // Returns whether the run should stop here (arrested and time.stop_on_arrest).
  bool update(double t_n, double last_new_arrival);
  bool arrested() const { return arrested_; } // at the last update

private:
  double quiet_after_; // the end of the ellipse (0 without it, and for a patch)
  double window_;
  bool stop_on_arrest_;
  bool arrested_ = false;
};

} // namespace slipfront
