// The front metrics of a run (docs/metrics.md "The slip front", "Rupture speed"), derived at
// its end from the per-node arrival times: the ruptured stretch, the arrest position, the
// propagation distance, the arrival at the probe, and the rupture-speed profile.
#pragma once

#include "solver/params.hpp"
#include "solver/run/metrics.hpp"

#include <vector>

namespace slipfront {

// Front speed from arrival times, by a centred difference of x1 against t_front over
// a window of +- half_window metres (nodes without arrival are skipped).
std::vector<double> rupture_speed_profile(const std::vector<double>& x1,
                                          const std::vector<double>& arrival_time,
                                          double half_window);

// The ruptured stretch of the interface: the run of consecutive nodes (periodic in x1) that
// slipped and that contains the nucleation patch's slipped nodes. Positions are unwrapped
// so that left <= right even when the stretch crosses the periodic seam.
struct RupturedStretch {
  bool ruptured = false; // a node outside the nucleation patch slipped
  bool any_slip = false;
  double left = 0, right = 0; // smallest and largest x1 reached [m]
  std::vector<int> nodes;     // node indices from left to right
};
RupturedStretch ruptured_stretch(const std::vector<double>& x1,
                                 const std::vector<double>& arrival_time, double patch_lo,
                                 double patch_hi, double width);

// The front profile (node positions, arrival times, V_r) and the front metrics of a run
// from the arrival times (NaN where the front never came): arrest position, propagation
// distance, arrival at probes.arrival_x1, max and mean V_r outside the nucleation patch;
// sets the outcome to no_rupture if nothing outside the patch slipped (unless diverged).
void derive_front_metrics(const SimulationParams& p, double dx,
                          const std::vector<double>& arrival_time, FrontProfile& front, Metrics& m);

} // namespace slipfront
