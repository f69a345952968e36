// Time series recorded during a run: the probe points, the stations and the energy balance.
#pragma once

#include <vector>

namespace slipfront {

// Time series recorded every step at the probe points.
struct ProbeRecords {
  std::vector<double> time;
  std::vector<double> slip_velocity_arrival;  // V at probes.arrival_x1
  std::vector<double> slip_velocity_spectrum; // V at probes.spectrum_x1
  std::vector<double> strength_spectrum;      // tau_s at probes.spectrum_x1
  double arrival_node_x1 = 0.0;               // the node nearest to the requested x1
  double spectrum_node_x1 = 0.0;
};

// Time series recorded every step at the on-fault stations (params.stations), each value
// w0 f(node0) + w1 f(node1) of the two nodes around the station (docs/hdf5-layout.md
// "/stations"). The series are row-major [time.size(), x1.size()]. Empty without stations.
struct StationRecords {
  std::vector<double> x1;              // the requested positions [m]
  std::vector<double> node_x1;         // [n, 2]: the two nodes around each station [m]
  std::vector<double> node_weight;     // [n, 2]: their weights (1, 0 on a node)
  double rupture_threshold = 0.0;      // [m/s]
  std::vector<double> time;            // t_n [s]
  std::vector<double> slip_rate;       // V [m/s]
  std::vector<double> slip;            // [m]
  std::vector<double> shear_traction;  // tau1 [Pa]
  std::vector<double> normal_traction; // -p [Pa], negative in compression
  std::vector<double> rupture_time;    // [n]: first |V| > threshold [s], NaN if never
  bool empty() const { return x1.empty(); }
};

// Energy balance sampled in time (perturbation energies, see docs/physics.md).
struct EnergyRecords {
  std::vector<double> time;
  std::vector<double> kinetic;
  std::vector<double> strain;
  std::vector<double> external_work; // work of the load changes (pre-stress release, nucleation)
  std::vector<double> dissipated;    // frictional dissipation
};

} // namespace slipfront
