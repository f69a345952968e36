// The friction laws a job can name: one line per coefficient law and per regularisation in
// the tables below (docs/architecture.md "Adding a friction law"). Each law lives in a file
// of its own beside this one and describes itself (law_description.hpp); the reader's
// choices, the schema and the labels come from these tables.
#include "solver/interface/friction/coefficient_law.hpp"
#include "solver/interface/friction/regularization_law.hpp"

#include <algorithm>
#include <stdexcept>

namespace slipfront {

// Defined in their own files.
const CoefficientLaw& prakash_clifton_law();
const CoefficientLaw& coulomb_law();
const CoefficientLaw& linear_slip_weakening_law();
const CoefficientLaw& rate_and_state_law();
const RegularizationLaw& no_regularization();
const RegularizationLaw& slip_scale_regularization();
const RegularizationLaw& time_scale_regularization();

namespace {

std::vector<const CoefficientLaw*>& coefficient_table() {
  static std::vector<const CoefficientLaw*> laws = {
      &prakash_clifton_law(),
      &coulomb_law(),
      &linear_slip_weakening_law(),
      &rate_and_state_law(),
  };
  return laws;
}

std::vector<const RegularizationLaw*>& regularization_table() {
  static std::vector<const RegularizationLaw*> laws = {
      &no_regularization(),
      &slip_scale_regularization(),
      &time_scale_regularization(),
  };
  return laws;
}

template <class Law>
const Law* find_in(const std::vector<const Law*>& table, std::string_view name) {
  for (const Law* law : table)
    if (law->description().name == name) return law;
  return nullptr;
}

template <class Law> void add_to(std::vector<const Law*>& table, const Law& law) {
  if (find_in(table, law.description().name))
    throw std::logic_error(std::string("friction law \"") + law.description().name +
                           "\" is registered twice");
  table.push_back(&law);
}

} // namespace

const std::vector<const CoefficientLaw*>& coefficient_laws() {
  return coefficient_table();
}

const CoefficientLaw* find_coefficient_law(std::string_view name) {
  return find_in(coefficient_table(), name);
}

const CoefficientLaw& coefficient_law(const Friction& friction) {
  if (const CoefficientLaw* law = find_coefficient_law(friction.law)) return *law;
  throw std::logic_error("no friction law \"" + friction.law + "\"");
}

void register_coefficient_law(const CoefficientLaw& law) {
  add_to(coefficient_table(), law);
}

const std::vector<const RegularizationLaw*>& regularization_laws() {
  return regularization_table();
}

const RegularizationLaw* find_regularization_law(std::string_view name) {
  return find_in(regularization_table(), name);
}

void register_regularization_law(const RegularizationLaw& law) {
  add_to(regularization_table(), law);
}

const RegularizationLaw& effective_regularization(const Friction& friction) {
  const char* fixed = coefficient_law(friction).fixed_regularization();
  const std::string_view name = *fixed ? std::string_view(fixed) : friction.regularization;
  if (const RegularizationLaw* law = find_regularization_law(name)) return *law;
  throw std::logic_error("no regularization \"" + std::string(name) + "\"");
}

FrictionState CoefficientLaw::initial_state(const Friction& /*job*/, const FrictionValues& values,
                                            double pressure, double /*shear_stress*/) const {
  return {static_coefficient(values) * std::max(0.0, pressure), 0.0, 0.0};
}

void CoefficientLaw::advance_state(const Friction& /*job*/, const FrictionValues& /*values*/,
                                   FrictionState& state, double slip_speed, double dt) const {
  state.slip_path += dt * slip_speed;
}

double CoefficientLaw::solve_slip_rate(const FrictionValues&, const FrictionState&, double, double,
                                       double, double) const {
  throw std::logic_error(std::string("friction law \"") + description().name +
                         "\" has a stick state: its slip rate is not solved for");
}

} // namespace slipfront
