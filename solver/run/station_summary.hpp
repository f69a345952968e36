// What a station's series say about the rupture there (docs/metrics.md "Other metrics"): the first
// time |V| exceeded a threshold, the peak slip rate and its time, the final slip. Derived
// after the run from the series the station recorder keeps at every step.
#pragma once

#include "solver/run/records.hpp"

#include <cstddef>

namespace slipfront {

struct StationSummary {
  double rupture_time;   // [s] first |V| > threshold, linear between steps; NaN if never
  double peak_slip_rate; // [m/s] the largest |V|
  double peak_time;      // [s] its (first) time
  double final_slip;     // [m] the slip at the last recorded step
};

// The summary of station s, its rupture time at `threshold` [m/s] (the recorder's own
// threshold gives its rupture_time exactly). NaN throughout for a station with no steps.
StationSummary summarize_station(const StationRecords& records, std::size_t s, double threshold);

} // namespace slipfront
