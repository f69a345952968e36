// The least-squares fit of the simplified Prakash-Clifton law (law_model.hpp) to a record's
// frictional stress where the interface slips (docs/length-fit.md "The fit"): L always, V*
// and mu when asked. A scan of L over the lengths the record can resolve, then
// Levenberg-Marquardt (Eigen) in ln L, ln V* and mu; the uncertainty from the Jacobian, the
// misfit and its correlation time, and from refits on every second sample.
#pragma once

#include "api/length_fit/interface_record.hpp"
#include "api/length_fit/law_model.hpp"
#include "api/length_fit/record_checks.hpp"

#include <optional>
#include <vector>

namespace slipfront::api {

struct LawFitSettings {
  double v_star = 1e-4; // V* [m/s]: the start of its fit when fit_v_star
  bool fit_v_star = false;
  std::optional<double> mu; // fixed when given, else fitted
};

// z of the two-sided 95 % interval of a normal distribution.
inline constexpr double interval_z = 1.959963984540054;

struct LawFit {
  LawParameters law; // the best fit (mu and V* as given when not fitted)
  bool v_star_fitted = false;
  bool mu_fitted = false;
  // ln L's standard error and the 95 % interval of L it gives: in quadrature, the statistical
  // error (from the Jacobian and the misfit, widened for the misfit's correlation; infinite
  // when the record does not determine L) and the sampling error (how far the fits of every
  // second sample, from the first or from the second, move ln L).
  double ln_L_standard_error = 0;
  double ln_L_statistical_error = 0;
  double ln_L_sampling_error = 0;
  double L_low = 0, L_high = 0;        // [m]
  double ln_v_star_standard_error = 0; // when fitted (else 0)
  double v_star_low = 0, v_star_high = 0;
  double mu_standard_error = 0; // when fitted (else 0)
  // The misfit over the slipping samples: its rms [Pa], its correlation time tau in samples
  // (1 + 2 x the sum of its autocorrelation up to the first lag where it is <= 0) and the
  // number of independent samples it leaves, m / tau.
  double rms_misfit = 0;
  double misfit_correlation_time = 1;
  double effective_samples = 0;
  std::size_t fitted_samples = 0; // m: the slipping samples
  // The lengths the scan covered: below L_min the law follows the pressure within a sample
  // step, above L_max it stays frozen over the record. At a limit, L is only bounded.
  double L_min = 0, L_max = 0;
  bool at_scan_limit = false;
  int iterations = 0;
  std::vector<double> fitted_stress; // tau_s of the fit at every sample [Pa]
};

LawFit fit_prakash_clifton(const InterfaceRecord& record, const SlippingSamples& slipping,
                           const LawFitSettings& settings);

} // namespace slipfront::api
