// Rate-and-state friction in both methods (docs/verification.md "Rate-and-state friction"):
// the interface step of a node (the traction is the strength at the slip rate it lets
// through), and a whole fault sliding uniformly between two identical solids, which is the
// radiation-damped slider: each solid radiates a plane S wave, so the traction is
// tau0 - (rho c_s / 2) V exactly, and V(t) follows from the state law alone. The slider is
// integrated here by fourth-order Runge-Kutta on theta (with V from the algebraic relation),
// and both methods must follow it from 1e-3 m/s through the instability to the new steady
// sliding near 0.8 m/s.
#include "solver/interface/friction/rate_state_math.hpp"
#include "solver/interface/interface_law.hpp"
#include "solver/simulation.hpp"
#include "verification_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace slipfront {
namespace {

Friction rate_and_state(StateEvolution evolution) {
  Friction f;
  f.law = "rate_and_state";
  f.state_evolution = evolution;
  f.a = 0.01;
  f.b = 0.015;
  f.f0 = 0.6;
  f.v_star = 1e-6;
  f.D_c = 1e-3;
  f.initial_slip_rate = 1e-3;
  f.initial_state = InitialState::steady_state;
  return f;
}

rate_state::Parameters law_parameters(const Friction& f) {
  return {f.a, f.b, f.D_c, f.f0, f.v_star};
}

TEST(RateStateNode, TheTractionIsTheStrengthAtTheSlipRateItLetsThrough) {
  // A node in contact with the plane: whatever its trial velocity, it slides (no stick state)
  // with tau_lock - eta V = sigma mu(V, theta), eta = m1 / (dt dx), and its strength is that
  // traction.
  const Friction f = rate_and_state(StateEvolution::aging);
  const InterfaceNodeConstants c{2.0, 2.0, 1e-3, 0.5, StrengthLaw(f)};
  const double sigma = 50e6, eta = c.mass1 / (c.dt * c.tributary_length);
  const FrictionState state = c.law.resting_state(f, sigma, 30e6);
  // The normal trial velocity that the plane stops with the pressure sigma.
  const double v2_trial = -sigma * c.dt * c.tributary_length / c.mass2;
  for (double v_trial : {-30.0, -1e-3, 1e-9, 5e-3, 0.1, 20.0}) {
    const InterfaceNodeStep s =
        resolve_interface_node(c, f, 0.0, v_trial, v2_trial, 1e-3, state, sigma);
    EXPECT_NEAR(s.pressure, sigma, 1e-9 * sigma);
    EXPECT_EQ(s.state, NodeState::slip) << v_trial;
    const double tau = -s.contact_force1 / c.tributary_length;
    EXPECT_NEAR(tau, eta * (v_trial - s.v1), 1e-9 * std::abs(tau) + 1e-6);
    // The strength in the step is sigma mu at the node's state after it, and |tau| equals it.
    EXPECT_NEAR(std::abs(tau), s.strength, 1e-9 * s.strength) << v_trial;
    EXPECT_NEAR(s.strength,
                sigma *
                    rate_state::coefficient(law_parameters(f), std::abs(s.v1), s.friction.theta),
                1e-9 * s.strength);
    EXPECT_TRUE(s.v1 * v_trial >= 0.0) << "V has the sign of the traction";
  }
}

// The radiation-damped slider: tau0 - eta V = sigma mu(V, theta), theta' by the state law,
// eta = rho c_s / 2 (two identical solids); RK4 on theta with a step of 1e-5 s.
struct Slider {
  std::vector<double> time, slip_rate;
};

Slider slider(const Friction& f, double tau0, double sigma, double eta, double duration) {
  const rate_state::Parameters p = law_parameters(f);
  auto speed = [&](double theta) {
    return rate_state::solve_slip_rate(p, theta, sigma, eta, tau0, f.initial_slip_rate).slip_rate;
  };
  auto rate = [&](double theta) {
    const double x = speed(theta) * theta / p.D_c;
    return f.state_evolution == StateEvolution::aging ? 1.0 - x : -x * std::log(x);
  };
  Slider s;
  double theta = rate_state::steady_state_theta(p, f.initial_slip_rate);
  const double h = 1e-5;
  for (int n = 0; n * h <= duration + 0.5 * h; ++n) {
    s.time.push_back(n * h);
    s.slip_rate.push_back(speed(theta));
    const double k1 = rate(theta), k2 = rate(theta + 0.5 * h * k1), k3 = rate(theta + 0.5 * h * k2),
                 k4 = rate(theta + h * k3);
    theta += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  return s;
}

// The first time V exceeds `threshold`, interpolated linearly (NaN if never).
double crossing(const std::vector<double>& t, const std::vector<double>& v, double threshold) {
  for (std::size_t k = 1; k < t.size(); ++k)
    if (v[k] > threshold && v[k - 1] <= threshold)
      return t[k - 1] + (threshold - v[k - 1]) / (v[k] - v[k - 1]) * (t[k] - t[k - 1]);
  return NAN;
}

// A narrow periodic strip (the motion is uniform) of two identical solids, with the state at
// steady sliding at 1e-3 m/s and tau0 0.2 MPa above what keeps it there: it accelerates.
SimulationParams uniform_scene(const std::string& method, StateEvolution evolution) {
  // Blocks tall enough that no reflection of the fast sliding returns within the run.
  SimulationParams p = verification::small_block(30.0, 2000.0, 0.1);
  p.method = method == "fe" ? Method::finite_element : Method::spectral_bi;
  p.material.density = 2670.0;
  p.material.young_modulus = 2670.0 * 3464.0 * 3464.0 * 2.0 * 1.25; // c_s 3464 m/s, nu 0.25
  p.lower.side = LowerSide::elastic;
  p.lower.material = p.material;
  p.lower.height = 2000.0;
  p.top = TopBoundary::absorbing;
  p.lower.bottom = TopBoundary::absorbing;
  p.friction = rate_and_state(evolution);
  p.loading.normal_stress = -100e6;
  const double eta = p.material.density * p.material.s_wave_speed() / 2.0;
  const rate_state::Parameters law = law_parameters(p.friction);
  p.loading.shear_stress =
      rate_state::steady_state_coefficient(law, 1e-3) * 100e6 + eta * 1e-3 + 0.2e6;
  p.stations.x1 = {0.0};
  p.stations.rupture_threshold = 0.1;
  p.time.duration = 2.0;
  p.output.interval = 0.1;
  return p;
}

TEST(RateStateScene, UniformSlidingIsTheRadiationDampedSlider) {
  for (const std::string method : {"spectral_bi", "fe"}) {
    for (StateEvolution evolution : {StateEvolution::aging, StateEvolution::slip}) {
      const SimulationParams p = uniform_scene(method, evolution);
      const double eta = p.material.density * p.material.s_wave_speed() / 2.0;
      const Slider ref = slider(p.friction, p.loading.shear_stress,
                                std::abs(p.loading.normal_stress), eta, p.time.duration);
      const RunResult r = run_simulation(p);
      const StationRecords& s = r.stations;
      ASSERT_FALSE(s.time.empty());
      const double t_ref = crossing(ref.time, ref.slip_rate, 0.1);
      const double t_run = crossing(s.time, s.slip_rate, 0.1);
      const double v_ref = ref.slip_rate.back(), v_run = s.slip_rate.back();
      const char* law = evolution == StateEvolution::aging ? "aging" : "slip";
      verification::measure("radiation-damped slider, %s law, %s: V > 0.1 m/s at %.6f s "
                            "(slider %.6f s, %+.2e), V(2 s) = %.6f m/s (slider %.6f, %+.2e)",
                            law, method.c_str(), t_run, t_ref, t_run / t_ref - 1, v_run, v_ref,
                            v_run / v_ref - 1);
      EXPECT_NEAR(t_run / t_ref, 1.0, 1e-3) << method << " " << law;
      EXPECT_NEAR(v_run / v_ref, 1.0, 1e-3) << method << " " << law;
    }
  }
}

} // namespace
} // namespace slipfront
