// Records the energy balance every 0.05 s of simulated time (the kinetic and strain sums
// are a sweep that does not vectorise, so the method evaluates them only on these steps).
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/run/records.hpp"

#include <utility>

namespace slipfront {

class EnergyRecorder {
public:
  explicit EnergyRecorder(double dt);

  bool due(long step) const { return step % every_ == 0; } // evaluate the energy in this step
  void record(const EnergyBalance& e, double t_n);         // stamped t_{n+1/2}
  const EnergyRecords& records() const { return records_; }
  EnergyRecords take() { return std::move(records_); }

private:
  double dt_;
  int every_;
  EnergyRecords records_;
};

} // namespace slipfront
