#include "api/friction_fields.hpp"

#include "solver/interface/friction/strength_law.hpp"

#include <algorithm>
#include <stdexcept>

namespace slipfront::api {

Interval interval_of(const Bounds& b) {
  return {b.min, b.max, b.min_open, b.max_open};
}

namespace {

bool contains(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

void add_once(std::vector<std::string>& list, const std::string& name) {
  if (!contains(list, name)) list.push_back(name);
}

// "meaning (law, law)": each distinct phrase with the laws that say it.
std::string joined_meaning(const std::vector<std::pair<std::string, std::string>>& phrases) {
  std::vector<std::pair<std::string, std::vector<std::string>>> groups;
  for (const auto& entry : phrases) {
    const std::string& phrase = entry.first;
    const std::string& law = entry.second;
    auto it = std::find_if(groups.begin(), groups.end(),
                           [&](const auto& g) { return g.first == phrase; });
    if (it == groups.end())
      groups.push_back({phrase, {law}});
    else
      add_once(it->second, law);
  }
  std::string out;
  for (const auto& [phrase, laws] : groups) {
    std::string names;
    for (const auto& law : laws)
      names += (names.empty() ? "" : ", ") + law;
    out += (out.empty() ? "" : "; ") + phrase + " (" + names + ")";
  }
  return out;
}

// What each law or regularisation says, in the order of the tables: a coefficient law's own
// description, or a regularisation's (with the laws that fix it).
struct Speaker {
  const LawDescription* description;
  std::vector<std::string> laws;            // the coefficient laws it speaks for
  std::vector<std::string> regularizations; // or the regularisation it is
};

std::vector<Speaker> speakers() {
  std::vector<Speaker> out;
  for (const CoefficientLaw* law : coefficient_laws())
    out.push_back({&law->description(), {law->description().name}, {}});
  for (const RegularizationLaw* reg : regularization_laws()) {
    Speaker s{&reg->description(), {}, {reg->description().name}};
    for (const CoefficientLaw* law : coefficient_laws())
      if (law->fixed_regularization() == std::string(reg->description().name))
        s.laws.push_back(law->description().name);
    out.push_back(std::move(s));
  }
  return out;
}

// "; also taken, and unused, by plain coulomb (...)" for a field some law still takes from
// its older records (LawDescription::legacy_fields).
std::string legacy_note(const std::string& field) {
  std::string laws;
  for (const CoefficientLaw* law : coefficient_laws())
    for (const char* name : law->description().legacy_fields)
      if (field == name) laws += std::string(laws.empty() ? "" : ", ") + law->description().name;
  if (laws.empty()) return "";
  return "; also taken, and unused, by " + laws +
         " without a regularization (its older records keep their hash)";
}

} // namespace

std::vector<FrictionField> friction_fields() {
  std::vector<FrictionField> fields;
  std::vector<std::vector<std::pair<std::string, std::string>>> phrases;
  for (const Speaker& s : speakers()) {
    for (const LawParameter& p : s.description->parameters) {
      auto it = std::find_if(fields.begin(), fields.end(),
                             [&](const FrictionField& f) { return f.name == p.name; });
      if (it == fields.end()) {
        fields.push_back({p.name, p.member, interval_of(p.allowed), p.unit, "", {}, {}});
        phrases.emplace_back();
        it = fields.end() - 1;
      } else if (it->member != p.member || it->unit != p.unit || it->allowed.lo != p.allowed.min ||
                 it->allowed.hi != p.allowed.max) {
        throw std::logic_error(std::string("friction field ") + p.name +
                               ": two laws describe it with different members, units or ranges");
      }
      for (const auto& law : s.laws)
        add_once(it->laws, law);
      for (const auto& reg : s.regularizations)
        add_once(it->regularizations, reg);
      for (const auto& law : s.laws)
        phrases[it - fields.begin()].push_back({p.meaning, law});
      for (const auto& reg : s.regularizations)
        phrases[it - fields.begin()].push_back({p.meaning, "regularization " + reg});
    }
  }
  for (std::size_t i = 0; i < fields.size(); ++i) {
    fields[i].meaning = joined_meaning(phrases[i]) + legacy_note(fields[i].name);
  }
  return fields;
}

std::vector<FrictionChoice> friction_choices() {
  std::vector<FrictionChoice> choices;
  std::vector<std::vector<std::pair<std::string, std::string>>> phrases;
  for (const Speaker& s : speakers()) {
    for (const LawChoice& c : s.description->choices) {
      auto it = std::find_if(choices.begin(), choices.end(), [&](const FrictionChoice& f) {
        return f.choice.name == std::string(c.name);
      });
      if (it == choices.end()) {
        choices.push_back({c, "", {}, {}});
        phrases.emplace_back();
        it = choices.end() - 1;
      }
      for (const auto& law : s.laws)
        add_once(it->laws, law);
      for (const auto& reg : s.regularizations)
        add_once(it->regularizations, reg);
      for (const auto& law : s.laws)
        phrases[it - choices.begin()].push_back({c.meaning, law});
      for (const auto& reg : s.regularizations)
        phrases[it - choices.begin()].push_back({c.meaning, "regularization " + reg});
    }
  }
  for (std::size_t i = 0; i < choices.size(); ++i)
    choices[i].meaning = joined_meaning(phrases[i]) + legacy_note(choices[i].choice.name);
  return choices;
}

std::vector<std::pair<std::string, std::string>> law_names() {
  std::vector<std::pair<std::string, std::string>> names;
  for (const CoefficientLaw* law : coefficient_laws())
    names.emplace_back(law->description().name, law->description().name);
  return names;
}

std::vector<std::pair<std::string, std::string>> regularization_names() {
  std::vector<std::pair<std::string, std::string>> names;
  for (const RegularizationLaw* reg : regularization_laws())
    names.emplace_back(reg->description().name, reg->description().name);
  return names;
}

nlohmann::json unregularized_patch(const Friction& friction) {
  const RegularizationLaw& regularization = effective_regularization(friction);
  if (!regularization.filters()) return nlohmann::json::object();
  const CoefficientLaw& law = coefficient_law(friction);
  Friction bare = friction;
  nlohmann::json patch = nlohmann::json::object();
  if (*law.fixed_regularization()) {
    bare.law = law.unregularized_law();
    patch["law"] = bare.law;
  } else {
    patch["regularization"] = "none";
  }
  bare.regularization = "none";
  const CoefficientLaw& after = coefficient_law(bare);
  auto taken = [&](const std::string& name) {
    for (const char* legacy : after.description().legacy_fields)
      if (name == legacy) return true;
    return false;
  };
  for (const LawParameter& p : regularization.description().parameters)
    if (!after.description().uses(p.member) && !taken(p.name)) patch[p.name] = nullptr;
  for (const LawChoice& c : regularization.description().choices)
    if (!taken(c.name)) patch[c.name] = nullptr;
  return patch;
}

std::string unregularized_label(const Friction& friction) {
  const CoefficientLaw& law = coefficient_law(friction);
  if (law.constant()) return "plain Coulomb";
  std::string name = law.description().name;
  std::replace(name.begin(), name.end(), '_', ' ');
  return name + " without regularisation";
}

std::string friction_field_name(double FrictionValues::*member) {
  for (const FrictionField& field : friction_fields())
    if (field.member == member) return field.name;
  return "";
}

std::string unused_friction_field(const Friction& friction) {
  const StrengthLaw law(friction);
  std::string used;
  for (const FrictionField& field : friction_fields())
    if (law.uses(field.member)) used += (used.empty() ? "" : ", ") + field.name;
  return "is not used by friction law \"" + friction.law + "\" with regularization \"" +
         law.regularization().description().name + "\" (it uses " +
         (used.empty() ? "none of them" : used) + ")";
}

} // namespace slipfront::api
