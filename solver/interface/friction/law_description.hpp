// What a friction law or a regularisation says of itself (docs/architecture.md "Adding a
// friction law"): its name, its numbers with their units, meanings and allowed ranges, its
// choices, the checks of its values and the label of a run. The job schema (fields, x-when),
// the reader's validation, the docs' tables of fields, the labels of the web view and the
// client are derived from it; nothing outside the law's own file spells its numbers.
// Plain data: the solver knows no JSON.
#pragma once

#include "solver/params.hpp"

#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace slipfront {

// The allowed range of a number: from min to max, each end open or closed (infinite:
// unbounded).
struct Bounds {
  double min = -std::numeric_limits<double>::infinity();
  bool min_open = false;
  double max = std::numeric_limits<double>::infinity();
  bool max_open = false;

  static Bounds positive() { return {0.0, true}; }
  static Bounds non_negative() { return {0.0, false}; }
  bool contains(double v) const {
    return (min_open ? v > min : v >= min) && (max_open ? v < max : v <= max);
  }
};

// A number of a law, one per interface node: the uniform value of `friction` that a
// `profiles` entry may override along x1. Its default is the FrictionValues member's.
struct LawParameter {
  const char* name;               // JSON spelling, in `friction` and in `profiles` entries
  double FrictionValues::*member; // where a node keeps it
  const char* unit;               // "" for a pure number
  const char* meaning;            // one phrase, for the schema and the docs
  Bounds allowed;
  // Whether a run with the job's choices reads it (empty: always).
  std::function<bool(const Friction&)> read_when = {};

  bool read_by(const Friction& job) const { return !read_when || read_when(job); }
};

// A choice of a law, one per job: a JSON string among `options`.
struct LawChoice {
  const char* name;                 // JSON spelling in `friction`
  const char* meaning;              // one phrase, for the schema and the docs
  std::vector<const char*> options; // the JSON spellings, in the schema's order
  std::function<int(const Friction&)> get;
  std::function<void(Friction&, int)> set;
};

// A problem of one node's values (mu_d > mu_s): the members it involves (the error names
// the field that set one of them last: a profiles entry or the uniform value) and why.
struct ValueProblem {
  std::vector<double FrictionValues::*> members;
  std::string reason; // "mu_d = 0.6 exceeds mu_s = 0.5 (the coefficient weakens)"
};

struct LawDescription {
  const char* name;    // JSON spelling of the law or regularisation
  const char* meaning; // one sentence, for the schema and the docs
  // The run's label, with {name} for a value of the law (its number, or its choice):
  // "slip weakening D_c = {D_c} m", "L = {L} m". A coefficient law's label comes first, its
  // regularisation's after it; `label_alone` is shown when both say nothing ("Coulomb").
  const char* label = "";
  const char* label_alone = "";
  std::vector<LawParameter> parameters;
  std::vector<LawChoice> choices;
  // The checks of one node's values beyond each number's range; empty: none.
  std::function<std::optional<ValueProblem>(const FrictionValues&)> check;
  // Records written before the law had its present fields: the fields it still takes and
  // does not use, so that they re-validate and keep their hash ("" = none), and whether its
  // canonical form leaves out a regularization of "none".
  std::vector<const char*> legacy_fields;
  bool omits_no_regularization = false;

  bool uses(double FrictionValues::*member) const {
    for (const LawParameter& p : parameters)
      if (p.member == member) return true;
    return false;
  }
};

} // namespace slipfront
