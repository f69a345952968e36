// Divergence of a run: a slip speed far above anything the loads can drive (1000 times the
// particle velocity that the whole remote load would cause, |tau| / (rho c_s)), a
// non-finite value anywhere (NaN fails the speed test; the energy sums on the steps they
// are evaluated), a strength outside its physical range (an unstable strength update), or a
// negative energy in a solid (a scheme that returns more energy than it received; each of
// two solids on its own).
// Also keeps the largest |V| seen (the max_slip_velocity metric).
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"

#include <string>

namespace slipfront {

class DivergenceCheck {
public:
  explicit DivergenceCheck(const SimulationParams& params);

  void check(const InterfaceFields& f);      // every step
  void check_energy(const EnergyBalance& e); // on the steps the energy was evaluated
  bool diverged() const { return diverged_; }
  // "diverged at t = ... s (step n): " and why.
  std::string message(double t_n, long step) const;

  double speed_limit() const { return speed_limit_; }
  double max_slip_velocity() const { return max_slip_velocity_; }

private:
  double mu_;
  bool two_solids_; // a lower elastic solid: passivity is checked per solid
  double speed_limit_;
  double max_coulomb_strength_; // the largest mu p seen, mu p0 included
  double max_slip_velocity_ = 0.0;
  bool diverged_ = false;
  std::string strength_message_;
  std::string energy_message_;
};

} // namespace slipfront
