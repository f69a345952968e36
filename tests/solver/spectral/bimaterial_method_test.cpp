// The spectral boundary-integral method with two elastic half-spaces
// (solver/spectral/spectral_method.hpp, docs/spectral-bi.md "Two half-spaces"):
//   - uniform slip and uniform opening: the uniform mode has no memory, so the two sides
//     respond as two dashpots in series, exactly (signs and masses of the split node);
//   - identical solids: the normal traction stays at its initial value to round-off while a
//     rupture slides the interface (the slip-induced normal stress of one side cancels the
//     other's), where the rigid plane changes it;
//   - a lower solid ever stiffer gives the rigid plane's run;
//   - the energy: the balance closes, and each half-space received a non-negative energy.
#include "verification_support.hpp"

#include "solver/spectral/spectral_method.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace slipfront {
namespace {

using verification::measure;

// The paper's solid above, `lower` below (a strip of the given width, n_d nodes per metre).
SimulationParams two_solids(double width, double nodes_per_meter, const Material& lower) {
  SimulationParams p = verification::small_block(width, 1.0, nodes_per_meter);
  p.method = Method::spectral_bi;
  p.lower.side = LowerSide::elastic;
  p.lower.material = lower;
  return p;
}

Material softer_and_lighter() {
  return {0.8, 1.6, 0.3};
} // c_s 0.877, c_p 1.641 (c_s+ = 1)

TEST(SpectralTwoSolids, UniformSlipIsTwoDashpotsInSeriesExactly) {
  for (const Material& lower : {Material{}, softer_and_lighter()}) {
    SimulationParams p = two_solids(2.0, 20.0, lower);
    p.friction.law = FrictionLaw::coulomb;
    p.friction.mu = 0.5;
    const double p0 = std::abs(p.loading.normal_stress), tau_r = p.friction.mu * p0;
    const double eta_up = p.material.density * p.material.s_wave_speed();
    const double eta_low = lower.density * lower.s_wave_speed();
    const double V = (p.loading.shear_stress - tau_r) * (1 / eta_up + 1 / eta_low);
    spectral::SpectralMethod method(p);
    double worst = 0, traction = 0, pressure = 0;
    for (int n = 0; n < 300; ++n) {
      method.step(false);
      const InterfaceFields& f = method.interface();
      for (int i = 0; i < method.nx(); ++i) {
        worst = std::max(worst, std::abs(f.half_velocity[i] / V - 1));
        traction = std::max(traction, std::abs(f.shear_traction[i] - tau_r) / tau_r);
        pressure = std::max(pressure, std::abs(f.pressure[i] - p0) / p0);
        EXPECT_EQ(f.state[i], std::int8_t(NodeState::slip));
      }
    }
    EXPECT_LT(worst, 1e-12);
    EXPECT_LT(traction, 1e-12);
    EXPECT_LT(pressure, 1e-12);
    measure("BI two solids, uniform slip (lower rho %.2g): V = %.6g m/s, max rel. error %.1e "
            "(traction %.1e, pressure %.1e)",
            lower.density, V, worst, traction, pressure);
  }
}

TEST(SpectralTwoSolids, UniformOpeningSeparatesTheSidesAtTheirImpedances) {
  const Material lower = softer_and_lighter();
  SimulationParams p = two_solids(2.0, 20.0, lower);
  const double pull = 0.025; // tensile: pulls the upper side up and the lower side down
  p.extra_load = [pull](double, double) { return InterfaceTraction{0.0, pull}; };
  const double p0 = std::abs(p.loading.normal_stress);
  const Material& up = p.material;
  const double V2 = (pull - p0) * (1 / (up.density * up.p_wave_speed()) +
                                   1 / (lower.density * lower.p_wave_speed()));
  const double V1 = p.loading.shear_stress * (1 / (up.density * up.s_wave_speed()) +
                                              1 / (lower.density * lower.s_wave_speed()));
  spectral::SpectralMethod method(p);
  double e1 = 0, e2 = 0, traction = 0;
  for (int n = 0; n < 300; ++n) {
    method.step(false);
    const InterfaceFields& f = method.interface();
    for (int i = 0; i < method.nx(); ++i) {
      e1 = std::max(e1, std::abs(f.half_velocity[i] / V1 - 1));
      traction = std::max({traction, std::abs(f.shear_traction[i]), std::abs(f.pressure[i])});
      EXPECT_EQ(f.state[i], std::int8_t(NodeState::open));
    }
    if (n > 0) e2 = std::max(e2, std::abs((f.opening[0] / (n * method.dt())) / V2 - 1));
  }
  EXPECT_LT(e1, 1e-12);
  EXPECT_LT(e2, 1e-12);
  EXPECT_EQ(traction, 0.0);
  measure("BI two solids, uniform opening: V1 rel. error %.1e, V2 rel. error %.1e", e1, e2);
}

// A sliding rupture without any normal load: an extra shear traction on |x1| <= 1.5 m lifts
// the shear above the strength there (Prakash-Clifton, L = 5e-5 m).
struct RuptureRecord {
  double pressure_change = 0; // max |p - p0| / p0 over every node and step
  double max_slip_rate = 0;
  double slipping_extent = 0;   // the largest |x1| that slipped
  double energy_balance = 0;    // |strain - (work - dissipated)| / work at the end
  double least_side_energy = 0; // min over steps of each half-space's energy / work
};

RuptureRecord sliding_rupture(SimulationParams p) {
  p.geometry.x_min = -10.0;
  p.time.duration = 6.0;
  p.extra_load = [](double x1, double) {
    return InterfaceTraction{std::abs(x1) <= 1.5 ? 0.004 : 0.0, 0.0};
  };
  spectral::SpectralMethod method(p);
  const double p0 = std::abs(p.loading.normal_stress);
  RuptureRecord r;
  r.least_side_energy = 1;
  while (method.time() < p.time.duration) {
    method.step(true);
    const InterfaceFields& f = method.interface();
    for (int i = 0; i < method.nx(); ++i) {
      r.pressure_change = std::max(r.pressure_change, std::abs(f.pressure[i] - p0) / p0);
      r.max_slip_rate = std::max(r.max_slip_rate, std::abs(f.velocity[i]));
      if (f.state[i] == std::int8_t(NodeState::slip))
        r.slipping_extent = std::max(r.slipping_extent, std::abs(f.x1[i]));
    }
    const EnergyBalance& e = method.energy();
    if (e.external_work > 0) {
      const double upper = e.strain - e.lower_solid;
      r.least_side_energy = std::min({r.least_side_energy, upper / e.external_work,
                                      p.lower.elastic() ? e.lower_solid / e.external_work : 1.0});
    }
  }
  const EnergyBalance& e = method.energy();
  r.energy_balance = std::abs(e.strain - (e.external_work - e.dissipated)) / e.external_work;
  return r;
}

TEST(SpectralTwoSolids, IdenticalSolidsKeepTheNormalTractionToRoundOff) {
  SimulationParams p = two_solids(20.0, 10.0, Material{});
  const RuptureRecord r = sliding_rupture(p);
  EXPECT_LT(r.pressure_change, 1e-12);
  EXPECT_GT(r.slipping_extent, 4.0) << "the rupture left the loaded patch";
  EXPECT_LT(r.energy_balance, 1e-12);
  EXPECT_GE(r.least_side_energy, 0.0);
  // The same rupture on the rigid plane changes the pressure (slip couples to the normal
  // stress of one half-space).
  p.lower.side = LowerSide::rigid;
  const RuptureRecord rigid = sliding_rupture(p);
  EXPECT_GT(rigid.pressure_change, 1e-3);
  measure("BI identical solids: max |p - p0|/p0 = %.1e during a rupture slipping to |x1| = "
          "%.1f m (max V %.3g m/s); rigid plane %.1e; energy balance %.1e, least side energy "
          "/ work %.3f",
          r.pressure_change, r.slipping_extent, r.max_slip_rate, rigid.pressure_change,
          r.energy_balance, r.least_side_energy);
}

// The rigid plane's run at the same time step (dt = beta dx / c_s of the stiff side, the rigid
// run's beta scaled to match): the slip of a Coulomb rupture differs by less and less.
double difference_from_rigid(double stiffness_factor) {
  SimulationParams p = two_solids(20.0, 10.0, Material{});
  p.geometry.x_min = -10.0;
  p.friction.law = FrictionLaw::coulomb;
  p.spectral.time_step_factor = 0.25;
  p.time.duration = 2.0;
  p.extra_load = [](double x1, double) {
    return InterfaceTraction{std::abs(x1) <= 1.5 ? 0.004 : 0.0, 0.0};
  };
  p.lower.material.young_modulus *= stiffness_factor; // its nu and rho fixed
  SimulationParams rigid = p;
  rigid.lower.side = LowerSide::rigid;
  rigid.spectral.time_step_factor *= p.material.s_wave_speed() / p.lower.material.s_wave_speed();
  spectral::SpectralMethod two(p), one(rigid);
  EXPECT_NEAR(two.dt(), one.dt(), 1e-15 * one.dt());
  while (one.time() < p.time.duration) {
    two.step(false);
    one.step(false);
  }
  double diff = 0, norm = 0;
  for (int i = 0; i < one.nx(); ++i) {
    diff = std::max(diff, std::abs(two.interface().slip[i] - one.interface().slip[i]));
    norm = std::max(norm, std::abs(one.interface().slip[i]));
  }
  return diff / norm;
}

TEST(SpectralTwoSolids, AStiffLowerSolidGivesTheRigidPlanesRun) {
  const double d10 = difference_from_rigid(1e2), d30 = difference_from_rigid(1e3);
  // The lower side's motion is that of its impedance eta- ~ sqrt(E-): the difference falls
  // like 1/sqrt(E-) at least.
  EXPECT_LT(d10, 0.05);
  EXPECT_LT(d30, d10 / std::sqrt(10.0) * 1.1);
  measure("BI two solids: max slip difference from the rigid plane's run, relative: %.2e at "
          "E- = 100 E+, %.2e at 1000 E+ (ratio %.2f)",
          d10, d30, d10 / d30);
}

} // namespace
} // namespace slipfront
