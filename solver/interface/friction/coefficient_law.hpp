// The coefficient law of friction: mu at a node from its state (docs/physics.md "Friction"),
// and the description every other part of slipfront derives the law's fields, checks and
// labels from (law_description.hpp). One file per law beside this one, registered in the
// table of friction_laws.cpp (docs/architecture.md "Adding a friction law").
#pragma once

#include "solver/interface/friction/law_description.hpp"
#include "solver/params.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace slipfront {

// What a node keeps of its friction from step to step.
struct FrictionState {
  double filtered = 0;  // c* = mu_0 sigma* [Pa], the regularisation's state
  double slip_path = 0; // s = integral of |V| dt [m]
  double theta = 0;     // the state variable of rate-and-state friction [s]
};

// How a coefficient law weakens with slip: mu falls by `drop` over the slip path `distance` [m]
// (slip weakening: mu_s - mu_d over D_c; rate-and-state: b over D_c). Its process zone at rest
// is factor mu* distance / (drop |sigma|) (mu* the interface's shear modulus), as `formula`
// writes it (api/scene_checks.cpp: the resolution check and the record's resolution).
struct Weakening {
  double drop = 0.0;
  double distance = 0.0;
  double factor = 1.0;
  const char* formula = "";
};

// A warning of a law about a valid scene (api/scene_checks.cpp shows it beside the field):
// the friction field it names ("a" for /friction/a) and why.
struct LawWarning {
  std::string field;
  std::string message;
};

// The FrictionValues a law reads (a profile may set only these).
using FrictionParameters = std::vector<double FrictionValues::*>;

class CoefficientLaw {
public:
  virtual ~CoefficientLaw() = default;
  virtual const LawDescription& description() const = 0;

  // The regularisation this law always runs with: prakash_clifton's slip scale ("" = the job
  // chooses it). The same coefficient with that regularisation chosen is this law (one physics,
  // one canonical form and hash).
  virtual const char* fixed_regularization() const { return ""; }
  // The law whose coefficient this one shares when it runs without its fixed regularisation
  // (prakash_clifton: coulomb); "" for a law without a fixed regularisation (its own
  // coefficient with regularization "none").
  virtual const char* unregularized_law() const { return ""; }
  // Whether mu stays the same whatever the slip and its rate (the spectral L_c estimate of the
  // slip-scale regularisation needs it, docs/metrics.md).
  virtual bool constant() const { return false; }
  // Whether the interface starts stuck: the initial shear stress at most mu_0 |sigma| outside
  // the nucleation patch. Laws of the slip rate have no stick state and start sliding.
  virtual bool starts_stuck() const { return true; }
  // Whether mu never exceeds mu_0, so that the strength stays within [0, mu_0 p]: the run's
  // divergence check (solver/run/divergence_check.hpp) tests a regularisation's update by it.
  virtual bool bounded_by_static() const { return true; }
  // The slip rate a node has before the first step (a law of the slip rate starts sliding).
  virtual double initial_slip_rate(const FrictionValues&) const { return 0.0; }
  // Whether the scene with this coefficient and no regularisation is a well-posed problem
  // whose mesh-converged answer regularised runs may be compared with (docs/studies-api.md
  // "L search"); `why` says which, and why (ill_posedness.cpp has the shared judgements).
  virtual bool well_posed_unregularized(const SimulationParams& params, std::string& why) const = 0;

  // mu_0: what the regularisation filters, c = mu_0 max(0, p).
  virtual double static_coefficient(const FrictionValues& values) const = 0;
  // mu of a node in `state` slipping at the rate |V| = slip_rate.
  virtual double coefficient(const FrictionValues& values, const FrictionState& state,
                             double slip_rate) const = 0;
  // The state of a node at rest under the pressure p and the shear stress tau (the job's
  // choices in `job`): c* = mu_0 max(0, p), no slip.
  virtual FrictionState initial_state(const Friction& job, const FrictionValues& values,
                                      double pressure, double shear_stress) const;
  // The law's own state over one step dt at the slip speed |V| (the slip path, here).
  virtual void advance_state(const Friction& job, const FrictionValues& values,
                             FrictionState& state, double slip_speed, double dt) const;

  // Laws of the slip rate (no stick state): the slip rate V of a node whose traction is
  // tau_lock - eta V (eta the method's impedance, tau_lock the traction that would hold it)
  // and equals the strength, sigma_star mu(|V|, state) sign(V). `guess` is the last |V|.
  virtual bool rate_dependent() const { return false; }
  virtual double solve_slip_rate(const FrictionValues& values, const FrictionState& state,
                                 double sigma_star, double eta, double tau_lock,
                                 double guess) const;
  // How mu weakens with slip (the scale of its process zone, D_c mu* / (drop sigma): the
  // resolution check of api/scene_checks.cpp); none for a constant coefficient.
  virtual std::optional<Weakening> weakening(const FrictionValues&) const { return std::nullopt; }
  // What the law warns of in a valid scene (rate and state: velocity strengthening on the
  // whole interface); none by default.
  virtual std::vector<LawWarning> scene_warnings(const SimulationParams&) const { return {}; }
};

// Every coefficient law a job can name, in the job schema's order (friction_laws.cpp), with
// the laws a test registered after them.
const std::vector<const CoefficientLaw*>& coefficient_laws();
// The law of that name, or null.
const CoefficientLaw* find_coefficient_law(std::string_view name);
// The law of friction.law; a job's law was checked by the reader (throws std::logic_error
// for a name no law has).
const CoefficientLaw& coefficient_law(const Friction& friction);
// Adds a law to the table (a test's toy law; the product's laws are in the table already).
void register_coefficient_law(const CoefficientLaw& law);

} // namespace slipfront
