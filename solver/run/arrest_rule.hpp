// The arrest rule (docs/metrics.md): the rupture has arrested once, after the nucleation
// has ended, no node has been newly reached by the front for time.arrest_window. The ellipse
// ends at its last time; an overstressed patch once the front has left it (before that the
// patch is still nucleating, however long that takes).
#pragma once

#include "solver/params.hpp"

#include <limits>

namespace slipfront {

class ArrestRule {
public:
  explicit ArrestRule(const SimulationParams& params);

  // After step n: last_new_arrival is the latest front arrival time (-inf if none),
  // first_arrival_outside the first one outside the nucleation patch (+inf if none yet).
  // Returns whether the run should stop here (arrested and time.stop_on_arrest).
  bool update(double t_n, double last_new_arrival,
              double first_arrival_outside = -std::numeric_limits<double>::infinity());
  bool arrested() const { return arrested_; } // at the last update

private:
  double quiet_after_; // the end of the ellipse (0 without it, and for a patch)
  bool patch_;         // an overstressed patch: watched from the first arrival outside it
  double window_;
  bool stop_on_arrest_;
  bool arrested_ = false;
};

} // namespace slipfront
