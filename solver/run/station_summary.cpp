#include "solver/run/station_summary.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront {

StationSummary summarize_station(const StationRecords& r, std::size_t s, double threshold) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  StationSummary out{nan, nan, nan, nan};
  const std::size_t n = r.x1.size(), steps = r.time.size();
  if (steps == 0 || s >= n) return out;
  out.peak_slip_rate = -1.0;
  for (std::size_t k = 0; k < steps; ++k) {
    const double v = std::abs(r.slip_rate[k * n + s]);
    if (v > out.peak_slip_rate) {
      out.peak_slip_rate = v;
      out.peak_time = r.time[k];
    }
    if (std::isnan(out.rupture_time) && v > threshold) {
      // The crossing, linear in time between step k - 1 (at or below) and step k (above), as
      // the recorder finds it while the run goes.
      if (k == 0) {
        out.rupture_time = r.time[0];
      } else {
        const double before = std::abs(r.slip_rate[(k - 1) * n + s]);
        const double fraction = std::clamp((threshold - before) / (v - before), 0.0, 1.0);
        out.rupture_time = std::isnan(fraction)
                               ? r.time[k]
                               : r.time[k - 1] + fraction * (r.time[k] - r.time[k - 1]);
      }
    }
  }
  out.final_slip = r.slip[(steps - 1) * n + s];
  return out;
}

} // namespace slipfront
