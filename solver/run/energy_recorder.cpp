#include "solver/run/energy_recorder.hpp"

#include "solver/step_count.hpp"

namespace slipfront {

EnergyRecorder::EnergyRecorder(double dt) : dt_(dt), every_(steps_per_interval(0.05, dt)) {}

void EnergyRecorder::record(const EnergyBalance& e, double t_n) {
  // The kinetic term holds v^{n+1/2}, the strain term u^n K u^{n+1}: both sit at t_{n+1/2}.
  records_.time.push_back(t_n + 0.5 * dt_);
  records_.kinetic.push_back(e.kinetic);
  records_.strain.push_back(e.strain);
  records_.external_work.push_back(e.external_work);
  records_.dissipated.push_back(e.dissipated);
}

double energy_balance_error(const EnergyRecords& e) {
  // E - E(0) = W - D with E(0) = 0 (docs/physics.md).
  if (e.time.empty()) return 0.0;
  const std::size_t k = e.time.size() - 1;
  const double stored = e.kinetic[k] + e.strain[k];
  const double net = e.external_work[k] - e.dissipated[k];
  const double scale = std::max({std::abs(e.external_work[k]), std::abs(stored), 1e-300});
  return std::abs(stored - net) / scale;
}

} // namespace slipfront
