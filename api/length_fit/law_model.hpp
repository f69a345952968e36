// The simplified Prakash-Clifton law (paper eq. 1) run along a record:
//   d tau_s/dt = -(|V| + V*)/L (tau_s - mu max(0, p)),
// from rest (tau_s = mu max(0, p) at the first sample), advanced from sample to sample by the
// solver's own strength update (solver/interface/friction/strength_law.hpp, the
// exponential_ramp update: exact for p linear and |V| frozen over the step), |V| over a step
// being the mean of its two samples (docs/length-fit.md "The fit").
#pragma once

#include "api/length_fit/interface_record.hpp"

#include <vector>

namespace slipfront::api {

struct LawParameters {
  double L = 0;      // [m]
  double v_star = 0; // [m/s]
  double mu = 0;
};

// tau_s at every sample of the record [Pa].
std::vector<double> prakash_clifton_strength(const InterfaceRecord& record,
                                             const LawParameters& law);

} // namespace slipfront::api
