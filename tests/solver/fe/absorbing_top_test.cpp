// The absorbing top (Lysmer-Kuhlemeyer dashpots, an option beside the paper's traction top):
// a plane wave at normal incidence must leave the block. Set-up of cases 4 and 5 (uniform
// slip, uniform opening) on a low block: with the traction top the interface velocity
// changes when the reflection returns at 2h/c; with the absorbing top it keeps the
// half-space value Delta sigma / (rho c) (a dashpot rho c is the exact impedance of the
// missing half-space for a normally incident plane wave).
#include "verification_support.hpp"

#include "solver/fe/mesh_stepper.hpp"
#include "solver/thread_team.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace slipfront::fe {
namespace {

using verification::measure;

struct Velocities {
  double before, after; // mean interface velocity before and after the first return (2h/c)
};

// Mean u-rate of the interface (component 0: slip, 1: opening) over [t0, t1].
Velocities interface_rates(SimulationParams p, int component, double t_return, double t_end) {
  MeshStepper mesh(p);
  ThreadTeam team(1);
  double ua = NAN, ub = NAN, uc = NAN, ud = NAN; // u at the sample times sa..sd
  double sa = NAN, sb = NAN, sc = NAN, sd = NAN;
  const double ta = 1.0, tb = t_return - 0.3, tc = t_return + 1.0, td = t_end;
  double energy_err = 0;
  while (mesh.time() < t_end + mesh.dt()) {
    mesh.step(team, true);
    const double t = mesh.time() - mesh.dt();
    const double u = component == 0 ? mesh.interface().slip[0] : mesh.interface().opening[0];
    if (std::isnan(ua) && t >= ta) ua = u, sa = t;
    if (t <= tb) ub = u, sb = t;
    if (std::isnan(uc) && t >= tc) uc = u, sc = t;
    if (t <= td) ud = u, sd = t;
    const EnergyBalance& e = mesh.energy();
    const double stored = e.kinetic + e.strain, net = e.external_work - e.dissipated;
    energy_err = std::max(energy_err, std::abs(stored - net) / std::abs(e.external_work));
  }
  EXPECT_LT(energy_err, 1e-10) << "energy balance with the dashpots";
  return {(ub - ua) / (sb - sa), (ud - uc) / (sd - sc)};
}

TEST(AbsorbingTop, NormallyIncidentSWaveLeavesTheBlock) {
  const double h = 4.0;
  SimulationParams p = verification::small_block(1.0, h, 20.0);
  p.friction.law = "coulomb";
  p.friction.mu = 0.5;
  const double V = (p.loading.shear_stress - 0.5 * std::abs(p.loading.normal_stress)) /
                   (p.material.density * p.material.s_wave_speed());
  const double t_return = 2 * h / p.material.s_wave_speed();
  p.top = TopBoundary::absorbing;
  const Velocities abs = interface_rates(p, 0, t_return, 3 * t_return);
  p.top = TopBoundary::traction;
  const Velocities free = interface_rates(p, 0, t_return, 3 * t_return);
  const double e_before = std::abs(abs.before / V - 1), e_after = std::abs(abs.after / V - 1);
  EXPECT_LT(e_before, 1e-3);
  EXPECT_LT(e_after, 1e-3);
  EXPECT_GT(std::abs(free.after / V - 1), 0.5) << "with the traction top the reflection returns";
  measure("absorbing top, S: V/V0 - 1 before return %.2e, after return %.2e (traction top "
          "after return: %.3f)",
          abs.before / V - 1, abs.after / V - 1, free.after / V - 1);
}

TEST(AbsorbingTop, NormallyIncidentPWaveLeavesTheBlock) {
  const double h = 4.0, pull = 0.025;
  SimulationParams p = verification::small_block(1.0, h, 20.0);
  p.extra_load = [pull](double, double) { return InterfaceTraction{0.0, pull}; };
  const double V2 =
      (pull - std::abs(p.loading.normal_stress)) / (p.material.density * p.material.p_wave_speed());
  const double t_return = 2 * h / p.material.p_wave_speed();
  p.top = TopBoundary::absorbing;
  const Velocities abs = interface_rates(p, 1, t_return, 3 * t_return);
  p.top = TopBoundary::traction;
  const Velocities free = interface_rates(p, 1, t_return, 3 * t_return);
  EXPECT_LT(std::abs(abs.before / V2 - 1), 1e-3);
  EXPECT_LT(std::abs(abs.after / V2 - 1), 1e-3);
  EXPECT_GT(std::abs(free.after / V2 - 1), 0.5);
  measure("absorbing top, P: V/V0 - 1 before return %.2e, after return %.2e (traction top "
          "after return: %.3f)",
          abs.before / V2 - 1, abs.after / V2 - 1, free.after / V2 - 1);
}

} // namespace
} // namespace slipfront::fe
