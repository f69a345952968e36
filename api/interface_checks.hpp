// Checks of the interface set-up along the whole interface (docs/api-job-spec.md
// "profiles", "nucleation"): the overstressed patch inside the domain with a node in it,
// and at every node outside the patch an initial state that is stuck (|tau0| <= mu_0
// |sigma0|) with mu_d <= mu_s; an error names the profiles entry (or the uniform field)
// that set the failing value last, and the x1 where it fails.
#pragma once

#include "api/job_spec.hpp"

#include <vector>

namespace slipfront::api {

void check_interface_setup(const JobSpec& job, std::vector<FieldError>& errors);

} // namespace slipfront::api
