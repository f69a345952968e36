// The friction values a job names, in `friction` and in `profiles` entries: their JSON
// spelling, the FrictionValues member each fills and its allowed range, defined once.
#pragma once

#include "api/json_fields.hpp"
#include "solver/params.hpp"

#include <string>
#include <vector>

namespace slipfront::api {

struct FrictionField {
  const char* name;
  double FrictionValues::*member;
  Interval allowed;
};

// mu, mu_s, mu_d, D_c, L, v_star, t_star (the reader's order).
const std::vector<FrictionField>& friction_fields();

// The spelling of a member ("" if it is none of them).
std::string friction_field_name(double FrictionValues::*member);

// Why a law has no use for a field: 'is not used by friction law "slip_weakening" with
// regularization "none" (it uses mu_s, mu_d, D_c)'.
std::string unused_friction_field(const Friction& friction);

} // namespace slipfront::api
