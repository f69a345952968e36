// The friction fields of a job, derived from the friction laws' descriptions
// (solver/interface/friction/law_description.hpp): every number and choice any law or
// regularisation names, once, with its range, unit, meaning and the laws that use it. The
// reader, the checks and the schema take them from here; no law's field is spelt in api/.
#pragma once

#include "api/json_fields.hpp"
#include "solver/interface/friction/regularization_law.hpp"

#include <string>
#include <vector>

namespace slipfront::api {

// A number of `friction` (and of `profiles` entries).
struct FrictionField {
  std::string name;
  double FrictionValues::*member;
  Interval allowed;
  std::string unit;
  std::string meaning;                      // each law's phrase and the laws that use it
  std::vector<std::string> laws;            // the coefficient laws that use it (directly or
                                            // through their fixed regularisation)
  std::vector<std::string> regularizations; // the regularisations that use it
};

// A choice of `friction` beside law and regularization (strength_update, ...).
struct FrictionChoice {
  LawChoice choice;
  std::string meaning;
  std::vector<std::string> laws, regularizations; // as for FrictionField
};

// In the order of the tables of laws: the coefficient laws' fields first, then the
// regularisations'; each field at its first mention.
std::vector<FrictionField> friction_fields();
std::vector<FrictionChoice> friction_choices();

// The JSON spellings of the coefficient laws and of the regularisations (the tables' order).
std::vector<std::pair<std::string, std::string>> law_names();
std::vector<std::pair<std::string, std::string>> regularization_names();

// The spelling of a member ("" if it is none of them).
std::string friction_field_name(double FrictionValues::*member);

// Why a law has no use for a field: 'is not used by friction law "slip_weakening" with
// regularization "none" (it uses mu_s, mu_d, D_c)'.
std::string unused_friction_field(const Friction& friction);

// The JSON merge patch of `friction` that takes the regularisation away and keeps the
// coefficient (an L search's companion runs, docs/studies-api.md "L search"): prakash_clifton
// becomes coulomb (its unregularised law), another law gets "regularization": "none", and the
// regularisation's fields the law then has no use for are removed. {} without a
// regularisation.
nlohmann::json unregularized_patch(const Friction& friction);

// What that companion is called in the study's pages and reports: "plain Coulomb" for a
// constant coefficient, else "<law> without regularisation" ("rate and state without
// regularisation").
std::string unregularized_label(const Friction& friction);

// The range of a law's number as the reader checks it.
Interval interval_of(const Bounds& bounds);

} // namespace slipfront::api
