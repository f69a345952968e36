// Linear slip weakening (Ida 1972; Andrews 1976; docs/physics.md "Friction"): the
// coefficient falls linearly from mu_s to mu_d over the slip path D_c and stays at mu_d,
//   mu(s) = mu_s - (mu_s - mu_d) min(s / D_c, 1).
#include "solver/interface/friction/coefficient_law.hpp"

#include <algorithm>

namespace slipfront {

namespace {

class LinearSlipWeakening final : public CoefficientLaw {
public:
  FrictionParameters parameters() const override {
    return {&FrictionValues::mu_s, &FrictionValues::mu_d, &FrictionValues::D_c};
  }
  double static_coefficient(const FrictionValues& v) const override { return v.mu_s; }
  double coefficient(const FrictionValues& v, double slip_path) const override {
    return v.mu_s - (v.mu_s - v.mu_d) * std::min(slip_path / v.D_c, 1.0);
  }
  std::optional<Weakening> weakening(const FrictionValues& v) const override {
    return Weakening{v.mu_s - v.mu_d, v.D_c};
  }
};

} // namespace

const CoefficientLaw& linear_slip_weakening() {
  static const LinearSlipWeakening law;
  return law;
}

} // namespace slipfront
