// The coefficient law of friction: mu as a function of the slip path s = integral of |V| dt
// at a node (docs/physics.md "Friction"). One file per law beside this one; the law a job
// names (params.friction.law) is picked in friction_laws.cpp.
#pragma once

#include "solver/params.hpp"

#include <optional>
#include <vector>

namespace slipfront {

// The FrictionValues a law reads (a profile may set only these).
using FrictionParameters = std::vector<double FrictionValues::*>;

// How a coefficient law weakens with slip: mu falls by `drop` over the slip path `distance` [m]
// (the scale of its process zone; api/scene_checks.cpp).
struct Weakening {
  double drop = 0.0;
  double distance = 0.0;
};

class CoefficientLaw {
public:
  virtual ~CoefficientLaw() = default;
  virtual FrictionParameters parameters() const = 0;
  // mu_0 = mu(0), the static coefficient: the regularisation filters mu_0 max(0, p).
  virtual double static_coefficient(const FrictionValues& values) const = 0;
  // mu(s) after a slip path s [m].
  virtual double coefficient(const FrictionValues& values, double slip_path) const = 0;
  // How mu weakens with slip; none for a constant coefficient.
  virtual std::optional<Weakening> weakening(const FrictionValues&) const { return std::nullopt; }
};

// A law of the job's choice with its job JSON spelling: a line of the tables in
// friction_laws.cpp.
template <class Kind, class Law> struct NamedLaw {
  Kind kind;
  const char* name;
  const Law* law;
};

// Every coefficient law (friction.law), in the job schema's order (friction_laws.cpp).
const std::vector<NamedLaw<FrictionLaw, CoefficientLaw>>& coefficient_laws();

// The law of params.friction.law, and its job JSON spelling.
const CoefficientLaw& coefficient_law(FrictionLaw law);
const char* to_string(FrictionLaw law);

} // namespace slipfront
