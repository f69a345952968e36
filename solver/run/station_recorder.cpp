#include "solver/run/station_recorder.hpp"

#include "solver/run/periodic_line.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront {

namespace {

constexpr double on_node_tolerance = 1e-9; // in node spacings, relative to the node index

// The nodes and weights of a station at x1: one node with weight 1 when x1 is on it (within
// round-off of x_min + i dx), else the two around it.
NodePair station_nodes(double x1, double x_min, double dx, int nx) {
  const double s = (x1 - x_min) / dx;
  const double nearest = std::round(s);
  if (std::abs(s - nearest) <= on_node_tolerance * std::max(1.0, std::abs(s))) {
    const int node = periodic_index(long(nearest), nx);
    return {node, node, 0.0};
  }
  return nodes_around(x1, x_min, dx, nx);
}

} // namespace

StationRecorder::StationRecorder(const Stations& stations, double x_min, double dx, int nx,
                                 long max_steps) {
  StationRecords& r = records_;
  r.x1 = stations.x1;
  r.rupture_threshold = stations.rupture_threshold;
  r.rupture_time.assign(r.x1.size(), std::numeric_limits<double>::quiet_NaN());
  for (double x1 : r.x1) {
    const NodePair p = station_nodes(x1, x_min, dx, nx);
    node0_.push_back(p.left);
    node1_.push_back(p.right);
    r.node_x1.insert(r.node_x1.end(), {x_min + p.left * dx, x_min + p.right * dx});
    r.node_weight.insert(r.node_weight.end(), {1.0 - p.weight, p.weight});
  }
  if (r.empty()) return;
  const auto rows = std::size_t(std::max(0L, max_steps));
  r.time.reserve(rows);
  for (std::vector<double>* series : {&r.slip_rate, &r.slip, &r.shear_traction, &r.normal_traction})
    series->reserve(rows * r.x1.size());
}

double StationRecorder::record_bytes(const Stations& stations, double steps) {
  if (stations.x1.empty()) return 0.0;
  const double n = double(stations.x1.size());
  return 8.0 * steps * (1.0 + 4.0 * n) + 8.0 * 5.0 * n; // series, then nodes and rupture times
}

double StationRecorder::at_station(const std::vector<double>& values, std::size_t s) const {
  const double w1 = records_.node_weight[2 * s + 1];
  const double v0 = values[node0_[s]];
  if (w1 == 0.0) return v0; // on a node: the node's value, exactly
  return records_.node_weight[2 * s] * v0 + w1 * values[node1_[s]];
}

void StationRecorder::record(const InterfaceFields& f, double t_n) {
  StationRecords& r = records_;
  if (r.empty()) return;
  const std::size_t row = r.time.size();
  r.time.push_back(t_n);
  for (std::size_t s = 0; s < r.x1.size(); ++s) {
    r.slip_rate.push_back(at_station(f.velocity, s));
    r.slip.push_back(at_station(f.slip, s));
    r.shear_traction.push_back(at_station(f.shear_traction, s));
    // The normal traction -p, < 0 in contact; 0 - p keeps an open node's 0 positive (not -0).
    r.normal_traction.push_back(0.0 - at_station(f.pressure, s));
  }
  update_rupture_times(row, t_n);
}

// The first step n whose |V_n| exceeds the threshold: the crossing time interpolated linearly
// between the step before and step n (the step's time when the first step already exceeds).
void StationRecorder::update_rupture_times(std::size_t row, double t_n) {
  StationRecords& r = records_;
  const std::size_t n = r.x1.size();
  for (std::size_t s = 0; s < n; ++s) {
    const double now = std::abs(r.slip_rate[row * n + s]);
    if (!std::isnan(r.rupture_time[s]) || !(now > r.rupture_threshold)) continue;
    if (row == 0) {
      r.rupture_time[s] = t_n;
      continue;
    }
    const double before = std::abs(r.slip_rate[(row - 1) * n + s]); // <= threshold
    const double t_before = r.time[row - 1];
    const double fraction = std::clamp((r.rupture_threshold - before) / (now - before), 0.0, 1.0);
    r.rupture_time[s] = std::isnan(fraction) ? t_n : t_before + fraction * (t_n - t_before);
  }
}

} // namespace slipfront
