#include "solver/run/divergence_check.hpp"

#include "solver/interface/interface_parameters.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slipfront {

DivergenceCheck::DivergenceCheck(const SimulationParams& params, const std::vector<double>& x1)
    : two_solids_(params.lower.elastic()),
      strength_bounded_(coefficient_law(params.friction).bounded_by_static()) {
  const CoefficientLaw& law = coefficient_law(params.friction);
  double load_scale = 0;
  for (const double x : x1) {
    const NodeParameters node = node_parameters(params, x);
    mu_0_.push_back(law.static_coefficient(node.friction));
    max_coulomb_strength_ =
        std::max(max_coulomb_strength_, mu_0_.back() * std::abs(node.normal_stress));
    load_scale = std::max(load_scale, std::abs(node.normal_stress) + std::abs(node.shear_stress));
  }
  speed_limit_ = 1000.0 * params.material.particle_velocity(load_scale);
}

void DivergenceCheck::check(const InterfaceFields& f) {
  const int nx = int(f.velocity.size());
  for (int i = 0; i < nx; ++i) {
    const double v = std::abs(f.velocity[i]);
    if (!(v <= speed_limit_)) diverged_ = true; // also catches NaN
    max_slip_velocity_ = std::max(max_slip_velocity_, v);
    max_coulomb_strength_ = std::max(max_coulomb_strength_, mu_0_[i] * f.pressure[i]);
  }
  // A stable strength update makes c* a convex combination of its start and the mu_0 p of
  // the step (friction/strength_update.hpp), and mu(s) <= mu_0, so tau_s stays within
  // [0, the largest mu_0 p seen, p0 included]; leaving that range means the update is unstable
  // even if it stays bounded (explicit Euler with dt (|V| + V*) / L > 2).
  for (int i = 0; i < nx && strength_message_.empty() && strength_bounded_; ++i) {
    const double ts = f.strength[i];
    if (ts < -1e-12 * max_coulomb_strength_ || ts > (1 + 1e-12) * max_coulomb_strength_) {
      char msg[240];
      std::snprintf(
          msg, sizeof msg,
          "frictional strength %.4g Pa at x1 = %.4g m left its physical range [0, %.4g] Pa: "
          "the strength update is unstable",
          ts, f.x1[i], max_coulomb_strength_);
      strength_message_ = msg;
    }
  }
  if (!strength_message_.empty()) diverged_ = true;
}

void DivergenceCheck::check_energy(const EnergyBalance& e) {
  if (!std::isfinite(e.kinetic) || !std::isfinite(e.strain)) diverged_ = true;
  // Passivity: a solid (the FE block's kinetic + strain energy, or the energy that crossed
  // into the BI half-space) cannot hold less than nothing. A negative value beyond round-off
  // means the discrete scheme gave back more energy than it received: it is unstable. With
  // two solids each is checked on its own.
  const double scale = std::max({std::abs(e.external_work), std::abs(e.dissipated), 1e-300});
  const double upper = e.kinetic + e.strain - e.lower_solid;
  const char* name = two_solids_ ? "the upper solid" : "the solid";
  double stored = upper;
  if (two_solids_ && e.lower_solid < upper) stored = e.lower_solid, name = "the lower solid";
  if (stored < -1e-9 * scale && energy_message_.empty()) {
    char msg[240];
    std::snprintf(msg, sizeof msg,
                  "the energy in %s became negative (%.4g J/m against %.4g J/m of load "
                  "work): the scheme returns more energy than it received",
                  name, stored, e.external_work);
    energy_message_ = msg;
    diverged_ = true;
  }
}

std::string DivergenceCheck::message(double t_n, long step) const {
  char msg[200];
  std::snprintf(msg, sizeof msg, "diverged at t = %.6g s (step %ld): ", t_n, step);
  std::string out = msg;
  if (!energy_message_.empty()) {
    out += energy_message_;
  } else if (strength_message_.empty()) {
    std::snprintf(msg, sizeof msg, "slip speed above %.3g m/s or a non-finite field", speed_limit_);
    out += msg;
  } else {
    out += strength_message_;
  }
  return out;
}

} // namespace slipfront
