// Rate-and-state friction, sinh-regularised (Lapusta et al. 2000; the form of SEM2DPACK, uguca
// and the SCEC TPV101-105 benchmarks; docs/physics.md "Rate-and-state friction"):
//   mu(V, theta) = a asinh[ |V| / (2 V*) exp((f0 + b ln(V* theta / D_c)) / a) ],
// with the aging law d theta/dt = 1 - |V| theta/D_c or the slip law
// d theta/dt = -(|V| theta/D_c) ln(|V| theta/D_c), integrated exactly at the step's slip
// speed (rate_state_math.hpp). The strength mu sigma* takes the regularisation the job
// chooses on top (sigma* of the Prakash-Clifton laws, Rubin & Ampuero 2007). It has no stick
// state: the traction is the strength at the slip rate it lets through, solved against the
// method's impedance at every node and step.
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/rate_state_math.hpp"
#include "solver/interface/ill_posedness.hpp"
#include "solver/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace slipfront {

namespace {

rate_state::Parameters parameters_of(const FrictionValues& v) {
  return {v.a, v.b, v.D_c, v.f0, v.v_star};
}

class RateAndState final : public CoefficientLaw {
public:
  const LawDescription& description() const override {
    static const LawDescription d = [] {
      LawDescription d;
      d.name = "rate_and_state";
      d.meaning = "sinh-regularised rate-and-state friction, a asinh[V/(2 V*) exp((f0 + b ln(V* "
                  "theta/D_c))/a)], with the aging or the slip law of the state theta";
      d.label = "rate and state ({state_evolution} law) a = {a}, b = {b}, D_c = {D_c} m";
      d.parameters = {
          {"a", &FrictionValues::a, "", "direct effect", Bounds::positive()},
          {"b", &FrictionValues::b, "", "evolution effect", Bounds::non_negative()},
          {"D_c", &FrictionValues::D_c, "m", "characteristic slip of the state evolution",
           Bounds::positive()},
          {"f0", &FrictionValues::f0, "", "steady-state coefficient at the slip rate V*",
           Bounds::non_negative()},
          {"v_star", &FrictionValues::v_star, "m/s", "reference slip rate V*", Bounds::positive()},
          {"theta", &FrictionValues::theta, "s",
           "initial state theta (with initial_state \"theta\")", Bounds::positive(),
           [](const Friction& f) { return f.initial_state == InitialState::theta; }},
          {"initial_slip_rate", &FrictionValues::initial_slip_rate, "m/s",
           "slip rate before the first step (the medium is at rest)", Bounds::positive()}};
      d.choices = {
          {"state_evolution",
           "the state law: `aging` (d theta/dt = 1 - \\|V\\| theta/D_c) or `slip` (d theta/dt = "
           "-(\\|V\\| theta/D_c) ln(\\|V\\| theta/D_c))",
           {"aging", "slip"},
           [](const Friction& f) { return int(f.state_evolution); },
           [](Friction& f, int i) { f.state_evolution = StateEvolution(i); }},
          {"initial_state",
           "the initial theta: `steady_state` (D_c / initial_slip_rate), `theta` (the value "
           "theta, and its profiles) or `stress` (the theta at which the strength at "
           "initial_slip_rate equals the initial shear stress, as SCEC TPV101)",
           {"steady_state", "theta", "stress"},
           [](const Friction& f) { return int(f.initial_state); },
           [](Friction& f, int i) { f.initial_state = InitialState(i); }}};
      return d;
    }();
    return d;
  }

  bool starts_stuck() const override { return false; }
  bool bounded_by_static() const override { return false; }
  bool rate_dependent() const override { return true; }
  double initial_slip_rate(const FrictionValues& v) const override { return v.initial_slip_rate; }

  bool well_posed_unregularized(const SimulationParams& params, std::string& why) const override {
    if (!params.lower.elastic()) {
      why = "not judged for rate-and-state friction on the rigid plane";
      return false;
    }
    const bool well_posed = two_solids_well_posed(params, why);
    if (!well_posed)
      why += "; rate-and-state friction does not regularise the instantaneous response to the "
             "normal stress (Rice, Lapusta & Ranjith 2001), the Prakash-Clifton regularisation "
             "does (Rubin & Ampuero 2007)";
    return well_posed;
  }

  // The process zone of rate-and-state at rest, Lambda_0 = mu* D_c / (b |sigma|) (Dieterich
  // 1992; Ampuero & Rubin 2008): it shrinks as the rupture speeds up.
  std::optional<Weakening> weakening(const FrictionValues& v) const override {
    return Weakening{v.b, v.D_c, 1.0,
                     "the rate-and-state process zone, mu* D_c / (b |normal_stress|)"};
  }

  // A coefficient that grows with the slip rate everywhere (a >= b, and no profile that changes
  // a or b) cannot host a rupture that grows on its own.
  std::vector<LawWarning> scene_warnings(const SimulationParams& p) const override {
    if (p.friction.a < p.friction.b) return {};
    for (const Profile& profile : p.profiles)
      for (const auto& [member, value] : profile.friction)
        if (member == &FrictionValues::a || member == &FrictionValues::b) return {};
    return {{"a", "a = " + number_text(p.friction.a, 4) +
                      " is at least b = " + number_text(p.friction.b, 4) +
                      " on the whole interface: velocity strengthening, where a rupture does "
                      "not grow on its own (it needs a - b < 0)"}};
  }

  // The regularisation filters sigma itself: mu_0 = 1, c* = sigma*.
  double static_coefficient(const FrictionValues&) const override { return 1.0; }
  double coefficient(const FrictionValues& v, const FrictionState& state,
                     double slip_rate) const override {
    return rate_state::coefficient(parameters_of(v), std::abs(slip_rate), state.theta);
  }

  FrictionState initial_state(const Friction& job, const FrictionValues& v, double pressure,
                              double shear_stress) const override {
    FrictionState state{std::max(0.0, pressure), 0.0, v.theta};
    const rate_state::Parameters p = parameters_of(v);
    switch (job.initial_state) {
    case InitialState::steady_state:
      state.theta = rate_state::steady_state_theta(p, v.initial_slip_rate);
      break;
    case InitialState::theta:
      break;
    case InitialState::stress: {
      // The strength at V_ini equals |tau0| (a node without a shear stress or a pressure gets
      // the smallest state, as weak as the law allows).
      const double mu = pressure > 0.0 ? std::abs(shear_stress) / pressure : 0.0;
      state.theta = mu > 0.0 ? rate_state::theta_for_coefficient(p, v.initial_slip_rate, mu)
                             : std::numeric_limits<double>::min();
      break;
    }
    }
    return state;
  }

  void advance_state(const Friction& job, const FrictionValues& v, FrictionState& state,
                     double slip_speed, double dt) const override {
    state.slip_path += dt * slip_speed;
    state.theta = rate_state::evolve_state(job.state_evolution, parameters_of(v), state.theta,
                                           slip_speed, dt);
  }

  double solve_slip_rate(const FrictionValues& v, const FrictionState& state, double sigma_star,
                         double eta, double tau_lock, double guess) const override {
    return rate_state::solve_slip_rate(parameters_of(v), state.theta, sigma_star, eta, tau_lock,
                                       guess)
        .slip_rate;
  }
};

} // namespace

const CoefficientLaw& rate_and_state_law() {
  static const RateAndState law;
  return law;
}

} // namespace slipfront
