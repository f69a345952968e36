// Records the energy balance every 0.05 s of simulated time (the kinetic and strain sums
// are a sweep that does not vectorise, so the method evaluates them only on these steps),
// and the balance's error at the last record (the energy_error metric, docs/physics.md
// "Energy balance").
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

// Energy balance at the last record: |E - (W - D)| / max(|W|, |E|), E = kinetic + strain
// (E(0) = 0); 0 without records.
double energy_balance_error(const EnergyRecords& energy);

} // namespace slipfront
