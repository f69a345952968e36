#include "api/friction_fields.hpp"

#include "solver/interface/friction/strength_law.hpp"

namespace slipfront::api {

const std::vector<FrictionField>& friction_fields() {
  static const std::vector<FrictionField> fields = {
      {"mu", &FrictionValues::mu, non_negative()},
      {"mu_s", &FrictionValues::mu_s, non_negative()},
      {"mu_d", &FrictionValues::mu_d, non_negative()},
      {"D_c", &FrictionValues::D_c, positive()},
      {"L", &FrictionValues::L, positive()},
      {"v_star", &FrictionValues::v_star, positive()},
      {"t_star", &FrictionValues::t_star, positive()},
  };
  return fields;
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
    if (law.uses(field.member)) used += (used.empty() ? "" : ", ") + std::string(field.name);
  return std::string("is not used by friction law \"") + to_string(friction.law) +
         "\" with regularization \"" + to_string(effective_regularization(friction)) +
         "\" (it uses " + (used.empty() ? "none of them" : used) + ")";
}

} // namespace slipfront::api
