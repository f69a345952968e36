// Divergence of a run: a slip speed far above anything the loads can drive (1000 times the
// particle velocity that the largest initial load of a node would cause, |tau| / (rho c_s)), a
// non-finite value anywhere (NaN fails the speed test; the energy sums on the steps they
// are evaluated), a strength outside its physical range (an unstable strength update), or a
// negative energy in a solid (a scheme that returns more energy than it received; each of
// two solids on its own).
// Also keeps the largest |V| seen (the max_slip_velocity metric).
#pragma once

#include "solver/interface/interface_fields.hpp"
#include "solver/params.hpp"

#include <string>
#include <vector>

namespace slipfront {

class DivergenceCheck {
public:
  // x1: the interface nodes (their initial stresses and static coefficients).
  DivergenceCheck(const SimulationParams& params, const std::vector<double>& x1);

  void check(const InterfaceFields& f);      // every step
  void check_energy(const EnergyBalance& e); // on the steps the energy was evaluated
  bool diverged() const { return diverged_; }
  // "diverged at t = ... s (step n): " and why.
  std::string message(double t_n, long step) const;

  double speed_limit() const { return speed_limit_; }
  double max_slip_velocity() const { return max_slip_velocity_; }

private:
  bool two_solids_;          // a lower elastic solid: passivity is checked per solid
  bool strength_bounded_;    // mu <= mu_0 for the law (not rate-and-state): tau_s is checked by it
  std::vector<double> mu_0_; // static coefficient of each node
  double speed_limit_ = 0;
  double max_coulomb_strength_ = 0; // the largest mu_0 p seen, mu_0 p0 included
  double max_slip_velocity_ = 0.0;
  bool diverged_ = false;
  std::string strength_message_;
  std::string energy_message_;
};

} // namespace slipfront
