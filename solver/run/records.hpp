// Time series recorded during a run: the probe points and the energy balance.
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

// Energy balance sampled in time (perturbation energies, see docs/physics.md).
struct EnergyRecords {
  std::vector<double> time;
  std::vector<double> kinetic;
  std::vector<double> strain;
  std::vector<double> external_work; // work of the load changes (pre-stress release, nucleation)
  std::vector<double> dissipated;    // frictional dissipation
};

} // namespace slipfront
