#include "api/interface_reader.hpp"

#include "api/friction_fields.hpp"
#include "api/number_text.hpp"
#include "solver/interface/friction/strength_law.hpp"

#include <algorithm>

namespace slipfront::api {

namespace {

nlohmann::json with_default(nlohmann::json schema, double value) {
  schema["default"] = value;
  return schema;
}

nlohmann::json choice_schema(const std::vector<const char*>& options, const std::string& current) {
  nlohmann::json list = nlohmann::json::array();
  for (const char* name : options)
    list.push_back(name);
  return {{"type", "string"}, {"enum", list}, {"default", current}};
}

nlohmann::json regularization_schema() {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, value] : regularization_names())
    list.push_back(name);
  return {{"type", "string"}, {"enum", list}, {"default", "none"}};
}

// Whether the law or its regularisation has the choice.
bool has_choice(const LawDescription& d, const std::string& name) {
  for (const LawChoice& c : d.choices)
    if (name == c.name) return true;
  return false;
}

bool listed(const std::vector<const char*>& names, const std::string& name) {
  return std::find_if(names.begin(), names.end(), [&](const char* n) { return name == n; }) !=
         names.end();
}

// The regularisation: the law's own, or the job's choice. A coefficient with the
// regularisation another law fixes is that law (coulomb + slip_scale = prakash_clifton: one
// physics, one canonical form and hash).
void read_regularization(ObjectReader& in, Friction& friction) {
  const CoefficientLaw& law = coefficient_law(friction);
  const std::string name = law.description().name;
  if (*law.fixed_regularization()) {
    const std::string other = law.unregularized_law();
    in.reject(
        "regularization",
        "is implied by law \"" + name + "\" (" + law.description().meaning + "): remove the field" +
            (other.empty()
                 ? std::string()
                 : " (for another regularisation of its coefficient use law \"" + other + "\")"),
        regularization_schema());
    return;
  }
  in.choice("regularization", friction.regularization, regularization_names());
  for (const CoefficientLaw* fixed : coefficient_laws()) {
    if (friction.regularization == fixed->fixed_regularization() &&
        name == fixed->unregularized_law()) {
      friction.law = fixed->description().name;
      friction.regularization = "none";
      in.set_canonical("law", friction.law);
      in.drop_canonical("regularization");
      return;
    }
  }
  // A law whose records predate the choice keeps their canonical form.
  if (law.description().omits_no_regularization && !effective_regularization(friction).filters())
    in.drop_canonical("regularization");
}

} // namespace

void read_friction(ObjectReader& in, Friction& friction) {
  in.choice("law", friction.law, law_names());
  read_regularization(in, friction);
  const CoefficientLaw& law = coefficient_law(friction);
  const RegularizationLaw& regularization = effective_regularization(friction);
  // Fields a law took before they meant anything to it (legacy_fields): still taken without a
  // regularisation, so that its records re-validate and keep their hash.
  auto legacy = [&](const std::string& field) {
    return !regularization.filters() && listed(law.description().legacy_fields, field);
  };
  const StrengthLaw strength(friction);
  for (const FrictionField& field : friction_fields()) {
    if (strength.uses(field.member) || legacy(field.name)) {
      in.number(field.name, friction.*field.member, field.allowed);
    } else {
      in.reject(field.name, unused_friction_field(friction),
                with_default(number_schema(field.allowed), friction.*field.member));
    }
  }
  for (const FrictionChoice& c : friction_choices()) {
    const std::vector<const char*>& options = c.choice.options;
    const bool used = has_choice(law.description(), c.choice.name) ||
                      has_choice(regularization.description(), c.choice.name) ||
                      legacy(c.choice.name);
    if (used) {
      std::vector<std::pair<std::string, int>> names;
      for (std::size_t i = 0; i < options.size(); ++i)
        names.emplace_back(options[i], int(i));
      int index = c.choice.get(friction);
      in.choice(c.choice.name, index, names);
      c.choice.set(friction, index);
    } else {
      std::string users;
      for (const auto& who : c.regularizations)
        users += (users.empty() ? "" : " or ") + who;
      for (const auto& who : c.laws)
        users += (users.empty() ? "law " : " or law ") + who;
      in.reject(c.choice.name,
                std::string("is used only with ") +
                    (c.regularizations.empty() ? "" : "a regularization (") + users +
                    (c.regularizations.empty() ? "" : ")"),
                choice_schema(options, options[std::size_t(c.choice.get(friction))]));
    }
  }
  if (law.description().check) {
    if (auto problem = law.description().check(friction))
      in.error(friction_field_name(problem->members.back()), problem->reason);
  }
}

void read_nucleation(ObjectReader& in, Nucleation& n) {
  in.boolean("enabled", n.enabled);
  in.choice("type", n.type,
            {{"ellipse", NucleationType::ellipse},
             {"overstressed_patch", NucleationType::overstressed_patch},
             {"stress_perturbation", NucleationType::stress_perturbation}});
  const bool ellipse = n.type == NucleationType::ellipse;
  const bool patch = n.type == NucleationType::overstressed_patch;
  const bool perturbation = n.type == NucleationType::stress_perturbation;
  if (ellipse) in.drop_canonical("type"); // the canonical form of the records before it existed
  auto field = [&](bool used, const char* key, double& target, const Interval& allowed,
                   const char* only) {
    if (used)
      in.number(key, target, allowed);
    else
      in.reject(key, std::string("is used only with \"type\": \"") + only + "\"",
                with_default(number_schema(allowed), target));
  };
  field(ellipse, "a", n.a, positive(), "ellipse");
  field(ellipse, "b", n.b, positive(), "ellipse");
  field(ellipse, "v", n.v, non_negative(), "ellipse");
  field(ellipse, "alpha", n.alpha, closed_interval(0.0, 1.0), "ellipse");
  field(patch, "x1_min", n.x1_min, any_finite(), "overstressed_patch");
  field(patch, "x1_max", n.x1_max, any_finite(), "overstressed_patch");
  field(patch, "shear_stress", n.shear_stress, any_finite(), "overstressed_patch");
  field(perturbation, "x1", n.x1, any_finite(), "stress_perturbation");
  field(perturbation, "radius", n.radius, positive(), "stress_perturbation");
  field(perturbation, "shear_stress_increase", n.shear_stress_increase, any_finite(),
        "stress_perturbation");
  field(perturbation, "rise_time", n.rise_time, positive(), "stress_perturbation");
}

namespace {

void read_profile(ObjectReader& in, const Friction& friction, Profile& profile) {
  const std::size_t errors_before = in.error_count();
  std::optional<double> lo, hi;
  in.optional_number("x1_min", lo, any_finite());
  in.optional_number("x1_max", hi, any_finite());
  in.boolean("outside", profile.outside);
  std::optional<double> ramp;
  in.optional_number("ramp", ramp, non_negative());
  if (ramp) profile.ramp = *ramp;
  in.optional_number("shear_stress", profile.shear_stress, any_finite());
  in.optional_number("normal_stress", profile.normal_stress, negative());
  const StrengthLaw law(friction);
  for (const FrictionField& field : friction_fields()) {
    if (!law.uses(field.member)) {
      in.reject(field.name, unused_friction_field(friction), number_schema(field.allowed));
      continue;
    }
    std::optional<double> value;
    in.optional_number(field.name, value, field.allowed);
    if (value) profile.friction.emplace_back(field.member, *value);
  }
  if (lo) profile.x1_min = *lo;
  if (hi) profile.x1_max = *hi;
  if (!in.present()) return;
  if (lo && hi && *lo > *hi)
    in.error("x1_min", "must be at most x1_max = " + number_text(*hi, 12) + ", got " +
                           number_text(*lo, 12) + " (the closed interval [x1_min, x1_max])");
  if (!profile.shear_stress && !profile.normal_stress && profile.friction.empty() &&
      in.error_count() == errors_before)
    in.error_here("sets nothing: give shear_stress, normal_stress or a value of the friction law");
}

} // namespace

void read_profiles(ObjectReader& in, const Friction& friction, std::vector<Profile>& profiles) {
  in.object_list("profiles", max_profiles, [&](ObjectReader& item, std::size_t) {
    Profile profile;
    read_profile(item, friction, profile);
    if (item.present()) profiles.push_back(std::move(profile));
  });
}

} // namespace slipfront::api
