// Records V and tau_s at the probe points (probes.arrival_x1, probes.spectrum_x1) every
// step, at the nodes nearest to the requested positions.
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"
#include "solver/run/records.hpp"

#include <utility>

namespace slipfront {

class ProbeRecorder {
public:
  // x1: the interface node positions (uniform spacing dx from geometry.x_min).
  ProbeRecorder(const Probes& probes, double x_min, double dx, const std::vector<double>& x1);

  void record(const InterfaceFields& f, double t_n);
  const ProbeRecords& records() const { return records_; }
  ProbeRecords take() { return std::move(records_); }

private:
  int arrival_node_, spectrum_node_;
  ProbeRecords records_;
};

} // namespace slipfront
