#include "api/interface_reader.hpp"

#include "api/friction_fields.hpp"
#include "api/number_text.hpp"
#include "solver/interface/friction/strength_law.hpp"

namespace slipfront::api {

namespace {

// The job JSON spellings of a table of laws (solver/interface/friction/friction_laws.cpp).
template <class Kind, class Law>
std::vector<std::pair<std::string, Kind>> names_of(const std::vector<NamedLaw<Kind, Law>>& laws) {
  std::vector<std::pair<std::string, Kind>> names;
  for (const auto& named : laws)
    names.emplace_back(named.name, named.kind);
  return names;
}

nlohmann::json enum_schema(const std::vector<std::pair<std::string, Regularization>>& names,
                           const std::string& default_name) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& [name, value] : names)
    list.push_back(name);
  return {{"type", "string"}, {"enum", list}, {"default", default_name}};
}

nlohmann::json with_default(nlohmann::json schema, double value) {
  schema["default"] = value;
  return schema;
}

void read_regularization(ObjectReader& in, Friction& friction) {
  const auto regularization_names = names_of(regularization_laws());
  if (friction.law == FrictionLaw::prakash_clifton) {
    in.reject("regularization",
              "is implied by law \"prakash_clifton\", the constant coefficient with the slip-scale "
              "regularisation of paper eq. 1: remove the field (for another regularisation of a "
              "constant coefficient use law \"coulomb\")",
              enum_schema(regularization_names, "none"));
    return;
  }
  in.choice("regularization", friction.regularization, regularization_names);
  // coulomb with the slip scale is prakash_clifton: one physics, one canonical form and hash.
  if (friction.law == FrictionLaw::coulomb &&
      friction.regularization == Regularization::slip_scale) {
    friction.law = FrictionLaw::prakash_clifton;
    friction.regularization = Regularization::none;
    in.set_canonical("law", "prakash_clifton");
    in.drop_canonical("regularization");
  }
  // Plain coulomb keeps the canonical form it had before the field existed.
  if (friction.law == FrictionLaw::coulomb && friction.regularization == Regularization::none)
    in.drop_canonical("regularization");
}

} // namespace

void read_friction(ObjectReader& in, Friction& friction) {
  in.choice("law", friction.law, names_of(coefficient_laws()));
  read_regularization(in, friction);
  const Regularization regularization = effective_regularization(friction);
  // Plain coulomb took L, v_star and strength_update before the regularisation was a
  // choice of its own (they did nothing): still taken, so that its records re-validate
  // and keep their hash.
  const bool plain_coulomb =
      friction.law == FrictionLaw::coulomb && regularization == Regularization::none;
  const StrengthLaw law(friction);
  for (const FrictionField& field : friction_fields()) {
    const bool legacy = plain_coulomb && (field.member == &FrictionValues::L ||
                                          field.member == &FrictionValues::v_star);
    if (law.uses(field.member) || legacy) {
      in.number(field.name, friction.*field.member, field.allowed);
    } else {
      in.reject(field.name, unused_friction_field(friction),
                with_default(number_schema(field.allowed), friction.*field.member));
    }
  }
  const std::vector<std::pair<std::string, StrengthUpdate>> updates = {
      {"exponential_ramp", StrengthUpdate::exponential_ramp},
      {"exponential", StrengthUpdate::exponential},
      {"explicit_euler", StrengthUpdate::explicit_euler}};
  if (regularization != Regularization::none || plain_coulomb) {
    in.choice("strength_update", friction.update, updates);
  } else {
    in.reject("strength_update", "is used only with a regularization (slip_scale or time_scale)",
              {{"type", "string"},
               {"enum", {"exponential_ramp", "exponential", "explicit_euler"}},
               {"default", "exponential_ramp"}});
  }
  if (friction.law == FrictionLaw::slip_weakening && friction.mu_d > friction.mu_s) {
    in.error("mu_d", "must be at most mu_s = " + number_text(friction.mu_s, 12) + ", got " +
                         number_text(friction.mu_d, 12) + " (the coefficient weakens)");
  }
}

void read_nucleation(ObjectReader& in, Nucleation& n) {
  in.boolean("enabled", n.enabled);
  in.choice("type", n.type,
            {{"ellipse", NucleationType::ellipse},
             {"overstressed_patch", NucleationType::overstressed_patch}});
  const bool ellipse = n.type == NucleationType::ellipse;
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
  field(!ellipse, "x1_min", n.x1_min, any_finite(), "overstressed_patch");
  field(!ellipse, "x1_max", n.x1_max, any_finite(), "overstressed_patch");
  field(!ellipse, "shear_stress", n.shear_stress, any_finite(), "overstressed_patch");
}

namespace {

void read_profile(ObjectReader& in, const Friction& friction, Profile& profile) {
  const std::size_t errors_before = in.error_count();
  std::optional<double> lo, hi;
  in.optional_number("x1_min", lo, any_finite());
  in.optional_number("x1_max", hi, any_finite());
  in.boolean("outside", profile.outside);
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
