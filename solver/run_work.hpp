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
  double rate_solves = 0;     // solves of a law of the slip rate (rate and state): nodes x steps
                              // x (1 + corrector passes); 0 for a law with a stick state
  double lag_steps = 0;       // BI: history lags convolved, summed over the steps, modes and
                              // solids
  double transform_steps = 0; // BI: steps x nx log2 nx, per solid
};

} // namespace slipfront
