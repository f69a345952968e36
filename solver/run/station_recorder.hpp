// Records the interface at the on-fault stations (params.stations) every step: slip rate,
// slip, shear traction and normal traction, each linearly interpolated between the two nodes
// around the station (exact on a node; the line is periodic), and the rupture time, the first
// time the station's |V| exceeds the threshold (docs/hdf5-layout.md "/stations").
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"
#include "solver/run/records.hpp"

#include <utility>

namespace slipfront {

class StationRecorder {
public:
  // nx interface nodes x_min + i dx; `max_steps`: the most steps the run may record (the
  // series are reserved for them once: memory the job's estimate counts, touched as recorded).
  StationRecorder(const Stations& stations, double x_min, double dx, int nx, long max_steps);

  // Bytes the records of `stations` hold after `steps` steps (the memory estimate's term).
  static double record_bytes(const Stations& stations, double steps);

  // Step n at t_n: the values of InterfaceFields at every station (nothing without stations).
  void record(const InterfaceFields& f, double t_n);
  const StationRecords& records() const { return records_; }
  StationRecords take() { return std::move(records_); }

private:
  // Value of a nodal quantity at station s.
  double at_station(const std::vector<double>& values, std::size_t s) const;
  // Sets the rupture time of the stations whose |V| first exceeds the threshold at t_n.
  void update_rupture_times(std::size_t row, double t_n);

  std::vector<int> node0_, node1_;
  StationRecords records_;
};

} // namespace slipfront
