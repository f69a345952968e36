// The length fit (api/length_fit/, docs/length-fit.md) on synthetic records whose L is known:
// the law integrated independently (length_fit_records.hpp), with and without noise; the
// verdict of paper Sec. 6 on a sharp and on a smooth event.
#include "api/length_fit/length_fit.hpp"
#include "api/number_text.hpp"
#include "length_fit_records.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <string>

namespace slipfront::api {
namespace {

using test::synthetic_record;
using test::SyntheticEvent;

LengthFit fit_or_fail(const InterfaceRecord& record, const LengthFitOptions& options = {}) {
  LengthFitOutcome out = fit_length(record, options);
  for (const RecordError& e : out.errors)
    ADD_FAILURE() << describe(e);
  EXPECT_TRUE(out.result.has_value());
  return out.result ? *out.result : LengthFit{};
}

bool inside(double value, double lo, double hi) {
  return lo <= value && value <= hi;
}

TEST(LengthFit, RecoversTheLengthOfANoiseFreeRecord) {
  for (double L : {3e-4, 1e-3, 1e-2}) {
    SyntheticEvent e;
    e.L = L;
    const LengthFit r = fit_or_fail(synthetic_record(e));
    const double error = std::abs(r.fit.law.L / L - 1);
    std::printf("[measured] L = %.0e m: L_m = %.6e m (error %.2e), 95 %% interval [%.4e, %.4e], "
                "mu = %.7f, correlation time %.1f, %zu samples fitted, %d iterations\n",
                L, r.fit.law.L, error, r.fit.L_low, r.fit.L_high, r.fit.law.mu,
                r.fit.misfit_correlation_time, r.fit.fitted_samples, r.fit.iterations);
    EXPECT_LT(error, 5e-3);
    EXPECT_TRUE(inside(L, r.fit.L_low, r.fit.L_high));
    EXPECT_NEAR(r.fit.law.mu, e.mu, 1e-4);
    EXPECT_FALSE(r.fit.at_scan_limit);
  }
}

// Gaussian noise on the stress (rms 1 % and 5 % of its range while slipping), 40 seeds each:
// the 95 % interval holds the true L in at least 36 of 40 records, and the fit stays close.
TEST(LengthFit, TheIntervalHoldsTheLengthOfNoisyRecords) {
  for (double noise : {0.01, 0.05}) {
    int covered = 0;
    double worst = 0, widest = 0;
    for (unsigned seed = 1; seed <= 40; ++seed) {
      SyntheticEvent e;
      e.noise = noise;
      e.seed = seed;
      const LengthFit r = fit_or_fail(synthetic_record(e));
      covered += inside(e.L, r.fit.L_low, r.fit.L_high);
      worst = std::max(worst, std::abs(r.fit.law.L / e.L - 1));
      widest = std::max(widest, r.fit.L_high / r.fit.law.L - 1);
    }
    std::printf("[measured] noise %.0f %%: the 95 %% interval holds L in %d of 40 records; "
                "largest error %.3f, widest upper half-interval %.3f\n",
                100 * noise, covered, worst, widest);
    EXPECT_GE(covered, 36);
    EXPECT_LT(worst, 20 * noise);
  }
}

TEST(LengthFit, FitsVStarWhenAsked) {
  SyntheticEvent e;
  e.v_star = 0.02; // comparable to the slip rate: it shapes the stress
  LengthFitOptions options;
  options.fit_v_star = true; // from the default start, the paper's 1e-4 m/s
  const LengthFit r = fit_or_fail(synthetic_record(e), options);
  std::printf("[measured] V* = 0.02 m/s, L = 1e-3 m: V*_m = %.5f m/s [%.5f, %.5f], L_m = %.5e m "
              "[%.4e, %.4e]\n",
              r.fit.law.v_star, r.fit.v_star_low, r.fit.v_star_high, r.fit.law.L, r.fit.L_low,
              r.fit.L_high);
  EXPECT_TRUE(r.fit.v_star_fitted);
  EXPECT_TRUE(inside(e.v_star, r.fit.v_star_low, r.fit.v_star_high));
  EXPECT_TRUE(inside(e.L, r.fit.L_low, r.fit.L_high));
  // V* given wrong by 100x and not fitted: the fit cannot be as good.
  LengthFitOptions wrong;
  wrong.v_star = 2.0;
  const LengthFit w = fit_or_fail(synthetic_record(e), wrong);
  EXPECT_GT(w.fit.rms_misfit, 10 * r.fit.rms_misfit);
}

TEST(LengthFit, GivenMuIsKept) {
  SyntheticEvent e;
  LengthFitOptions options;
  options.mu = 0.6;
  const LengthFit r = fit_or_fail(synthetic_record(e), options);
  EXPECT_FALSE(r.fit.mu_fitted);
  EXPECT_EQ(r.fit.law.mu, 0.6);
  EXPECT_TRUE(inside(e.L, r.fit.L_low, r.fit.L_high));
}

// Paper Sec. 6: f_m from L_c(f_m) = L_m; the event is rich when more than 1 % of the pressure's
// power lies above f_m. A long L (1e-2 m: f_m = 0.16 Hz under a 2 Hz wiggle) is measured; a
// short one (1e-5 m: f_m = 160 Hz, above the record's 25 Hz Nyquist) is only bounded.
TEST(LengthFit, VerdictFollowsThePowerAboveTheMeasuredCriticalFrequency) {
  SyntheticEvent rich;
  rich.L = 1e-2;
  const LengthFit a = fit_or_fail(synthetic_record(rich));
  const double expected_f_m = std::sqrt(1 / (0.98 * 0.98) - 1) *
                              (a.peak_slip_rate + a.fit.law.v_star) /
                              (2 * std::numbers::pi * a.fit.law.L);
  EXPECT_NEAR(a.critical_frequency, expected_f_m, 1e-12 * expected_f_m);
  EXPECT_TRUE(a.verdict.rich_enough);
  EXPECT_GT(a.verdict.power_above_f_m, 0.01);
  EXPECT_LT(a.verdict.event_critical_length, a.fit.law.L);
  EXPECT_NE(a.verdict.text.find("rich enough"), std::string::npos);

  SyntheticEvent smooth;
  smooth.L = 1e-5;
  const LengthFit b = fit_or_fail(synthetic_record(smooth));
  EXPECT_FALSE(b.verdict.rich_enough);
  EXPECT_LE(b.verdict.power_above_f_m, 0.01);
  EXPECT_GE(b.verdict.upper_bound, smooth.L); // the bound holds
  EXPECT_NE(b.verdict.text.find("not rich enough"), std::string::npos);
  std::printf("[measured] L = 1e-2 m: f_m = %.3g Hz, %.1f %% of the power above, event L_c %.3g m "
              "-> rich; L = 1e-5 m: L_m = %.3g m, f_m = %.3g Hz, %.2g %% above, bound %.3g m\n",
              a.critical_frequency, 100 * a.verdict.power_above_f_m,
              a.verdict.event_critical_length, b.fit.law.L, b.critical_frequency,
              100 * b.verdict.power_above_f_m, b.verdict.upper_bound);
}

// The verdict's words cannot be read as contradicting its numbers: rich, it names L_m as the
// length; not rich, it names one bound, at least every length it mentions, says that L_m lies
// below it, and never calls L_m itself the bound.
TEST(LengthFit, VerdictWordsAgreeWithTheirNumbers) {
  SyntheticEvent rich;
  rich.L = 1e-2;
  const LengthFit a = fit_or_fail(synthetic_record(rich));
  EXPECT_EQ(a.verdict.text, "the event is rich enough: the interface's physical length is L_m = " +
                                slipfront::api::number_text(a.fit.law.L, 3) + " m");
  SyntheticEvent smooth;
  smooth.L = 1e-5;
  const LengthFit b = fit_or_fail(synthetic_record(smooth));
  const std::string& text = b.verdict.text;
  const std::string bound =
      "at most " + slipfront::api::number_text(b.verdict.upper_bound, 3) + " m";
  EXPECT_NE(text.find(bound), std::string::npos) << text;
  EXPECT_NE(
      text.find("L_m = " + slipfront::api::number_text(b.fit.law.L, 3) + " m, below that bound"),
      std::string::npos)
      << text;
  EXPECT_LE(b.fit.law.L, b.verdict.upper_bound);
  EXPECT_GE(b.verdict.upper_bound, b.verdict.event_critical_length);
  EXPECT_EQ(text.find("L_m is only an upper bound"), std::string::npos) << text;
  // Every length in metres the text names is at most the bound.
  std::size_t at = 0;
  while ((at = text.find(" m", at)) != std::string::npos) {
    std::size_t start = text.rfind(' ', at - 1) + 1;
    const std::string number = text.substr(start, at - start);
    char* end = nullptr;
    const double value = std::strtod(number.c_str(), &end);
    if (end != number.c_str() && *end == '\0') {
      EXPECT_LE(value, b.verdict.upper_bound * (1 + 1e-3)) << number << " in: " << text;
    }
    at += 2;
  }
}

// Unevenly sampled records are resampled for the spectrum and fitted as they are.
TEST(LengthFit, UnevenSamplesAreFitted) {
  SyntheticEvent e;
  e.samples = 1000;
  InterfaceRecord all = synthetic_record(e), uneven;
  for (std::size_t k = 0; k < all.size(); ++k) {
    if (k % 3 == 1) continue; // steps alternate between 2 dt and dt
    for (std::size_t c = 0; c < record_column_count; ++c)
      uneven.column(RecordColumn(c)).push_back(all.column(RecordColumn(c))[k]);
  }
  const LengthFit r = fit_or_fail(uneven);
  EXPECT_TRUE(r.spectrum.resampled);
  EXPECT_TRUE(inside(e.L, r.fit.L_low, r.fit.L_high));
  EXPECT_LT(std::abs(r.fit.law.L / e.L - 1), 0.01);
}

} // namespace
} // namespace slipfront::api
