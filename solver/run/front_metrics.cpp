#include "solver/run/front_metrics.hpp"

#include "solver/interface/nucleation.hpp"
#include "solver/run/periodic_line.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront {

std::vector<double> rupture_speed_profile(const std::vector<double>& x1,
                                          const std::vector<double>& arrival_time,
                                          double half_window) {
  // V_r = 1 / (d t_front / d x1), the slope from a least-squares line through the arrival
  // times of the nodes within +- half_window (a smoothing, centred derivative).
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int n = int(x1.size());
  std::vector<double> speed(n, nan);
  for (int i = 0; i < n; ++i) {
    if (std::isnan(arrival_time[i])) continue;
    double sx = 0, st = 0, sxx = 0, sxt = 0;
    int count = 0;
    for (int k = i - 1; k >= 0 && x1[i] - x1[k] <= half_window && !std::isnan(arrival_time[k]);
         --k) {
      sx += x1[k], st += arrival_time[k], sxx += x1[k] * x1[k], sxt += x1[k] * arrival_time[k];
      ++count;
    }
    for (int k = i; k < n && x1[k] - x1[i] <= half_window && !std::isnan(arrival_time[k]); ++k) {
      sx += x1[k], st += arrival_time[k], sxx += x1[k] * x1[k], sxt += x1[k] * arrival_time[k];
      ++count;
    }
    if (count < 3) continue;
    const double slope = (count * sxt - sx * st) / (count * sxx - sx * sx); // dt/dx1
    if (slope > 0) speed[i] = 1.0 / slope;
  }
  return speed;
}

RupturedStretch ruptured_stretch(const std::vector<double>& x1,
                                 const std::vector<double>& arrival_time, double patch_lo,
                                 double patch_hi, double width) {
  RupturedStretch out;
  const int n = int(x1.size());
  auto slipped = [&](int i) { return !std::isnan(arrival_time[periodic_index(i, n)]); };
  // Seed: the earliest node that slipped inside the nucleation patch, else the earliest
  // node anywhere.
  int seed = -1;
  for (int pass = 0; pass < 2 && seed < 0; ++pass)
    for (int i = 0; i < n; ++i) {
      if (!slipped(i)) continue;
      if (pass == 0 && (x1[i] < patch_lo || x1[i] > patch_hi)) continue;
      if (seed < 0 || arrival_time[i] < arrival_time[seed]) seed = i;
    }
  if (seed < 0) return out;
  out.any_slip = true;
  int lo = seed, hi = seed;
  while (hi - lo + 1 < n && slipped(lo - 1))
    --lo;
  while (hi - lo + 1 < n && slipped(hi + 1))
    ++hi;
  const double dx = width / n;
  auto unwrapped_x = [&](int i) {
    return x1[periodic_index(i, n)] + std::floor(double(i) / n) * width;
  };
  out.left = unwrapped_x(lo);
  out.right = unwrapped_x(hi);
  for (int i = lo; i <= hi; ++i)
    out.nodes.push_back(periodic_index(i, n));
  out.ruptured = out.left < patch_lo - 0.5 * dx || out.right > patch_hi + 0.5 * dx;
  return out;
}

void derive_front_metrics(const SimulationParams& p, double dx,
                          const std::vector<double>& arrival_time, FrontProfile& front,
                          Metrics& m) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const int nx = int(arrival_time.size());
  const Interval patch = nucleation_patch(p.nucleation); // empty without nucleation
  front.x1.resize(nx);
  for (int i = 0; i < nx; ++i)
    front.x1[i] = p.geometry.x_min + i * dx;
  front.arrival_time = arrival_time;
  front.rupture_speed.assign(nx, nan);

  const RupturedStretch stretch =
      ruptured_stretch(front.x1, front.arrival_time, patch.lo, patch.hi, p.geometry.width);
  m.arrest_position = stretch.any_slip ? stretch.right : nan;
  m.propagation_distance = stretch.any_slip ? stretch.right - stretch.left : 0.0;
  m.probe_x1 = p.probes.arrival_x1;
  m.arrival_time_at_probe =
      interpolate_nodal(front.arrival_time, p.probes.arrival_x1, p.geometry.x_min, dx);

  // V_r along the stretch, on unwrapped positions; max and mean outside the nucleation patch
  // (inside it the nucleation, not the rupture, sets the front).
  std::vector<double> xs, ts;
  for (std::size_t k = 0; k < stretch.nodes.size(); ++k) {
    xs.push_back(stretch.left + double(k) * dx);
    ts.push_back(front.arrival_time[stretch.nodes[k]]);
  }
  const std::vector<double> vr = rupture_speed_profile(xs, ts, std::max(0.25, 2.0 * dx));
  double vmax = nan, vsum = 0;
  int count = 0;
  for (std::size_t k = 0; k < stretch.nodes.size(); ++k) {
    front.rupture_speed[stretch.nodes[k]] = vr[k];
    if (std::isnan(vr[k]) || (xs[k] >= patch.lo && xs[k] <= patch.hi)) continue;
    vmax = std::isnan(vmax) ? vr[k] : std::max(vmax, vr[k]);
    vsum += vr[k];
    ++count;
  }
  m.max_rupture_speed = vmax;
  m.mean_rupture_speed = count > 0 ? vsum / count : nan;
  if (m.outcome != Outcome::diverged && !stretch.ruptured) m.outcome = Outcome::no_rupture;
  if (stretch.nodes.size() == std::size_t(nx))
    m.warnings.push_back(
        "the whole periodic interface slipped: the rupture met itself across the seam");
}

} // namespace slipfront
