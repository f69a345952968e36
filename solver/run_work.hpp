// The work of a run before it starts: the counts a cost model times (api/cost_estimate.hpp,
// docs/performance.md "Cost estimate"); each method counts its own (its estimated_work).
#pragma once

namespace slipfront {

struct RunWork {
  double steps = 0;           // time steps to reach the time asked for
  double dt = 0;              // [s] the time step (FE: to 5 digits, as the stable step is)
  double node_steps = 0;      // FE: nodes swept, summed over the steps (x2.7 with mesh damping)
  double row_steps = 0;       // FE: rows swept (of both blocks), summed over the steps
  double interface_steps = 0; // interface nodes x steps (both methods)
  double lag_steps = 0;       // BI: history lags convolved, summed over the steps and modes
  double lower_lag_steps = 0; // BI: the same of the lower half-space (0 on the rigid plane)
  double transform_steps = 0; // BI: steps x nx log2 nx, per solid
};

} // namespace slipfront
