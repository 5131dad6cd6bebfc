// SPDX-License-Identifier: BSD-3-Clause
// Carrying a fit-data report's Hertz fit over (restitution/fit.hpp), as `dem --from-fit` and `calibrate
// --from-fit` do: the report's own verdict on the fit (judge_reported_fit: the χ² test against the χ²
// distribution's 1 % point, never with σ estimated; another law with a lower AIC unless tied; the residual
// tests' trends, not their "none"), and the ε its β and intervals give at one speed (fitted_eps_at_speed:
// the bounds swap, an edge stays an edge).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "restitution/errors.hpp"
#include "restitution/fast.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace {

using namespace restitution;

ReportedFit hertz(double chi2, double aic, const char* verdict = "none") {
  return {LawKind::viscoelastic_hertz, CollisionEnd::delayed_recovery, chi2, aic, verdict};
}

// χ² of one degree of freedom exceeds 6.634897 with probability 1 % (the 99 % quantile).
constexpr double kChi2OneDofOnePercent = 6.634897;

TEST(FitRejection, ChiSquareAtTheOnePercentPoint) {
  const std::vector<ReportedFit> above{hertz(kChi2OneDofOnePercent * 1.01, 0.0)};
  const FitRejection a = judge_reported_fit(above, 0, 0, {}, false, 2);
  ASSERT_TRUE(a.chi2_per_dof.has_value());
  EXPECT_DOUBLE_EQ(*a.chi2_per_dof, kChi2OneDofOnePercent * 1.01);  // 1 degree of freedom
  EXPECT_LT(a.chi2_p_value, kFitSignificance);
  EXPECT_TRUE(a.rejected());
  const std::vector<ReportedFit> below{hertz(kChi2OneDofOnePercent * 0.99, 0.0)};
  EXPECT_FALSE(judge_reported_fit(below, 0, 0, {}, false, 2).rejected());
  // With σ estimated χ²/dof is that estimate: the test says nothing however large.
  EXPECT_FALSE(judge_reported_fit(above, 0, 0, {}, true, 2).rejected());
}

TEST(FitRejection, AnotherLawWithALowerAicUnlessTied) {
  std::vector<ReportedFit> fits{hertz(1.0, 10.0), hertz(1.0, 5.0)};
  fits[1].law = LawKind::tsuji_hertz;
  const FitRejection r = judge_reported_fit(fits, 0, 1, {}, true, 10);
  ASSERT_TRUE(r.better_fit.has_value());
  EXPECT_EQ(*r.better_fit, 1U);
  EXPECT_FALSE(judge_reported_fit(fits, 0, 1, {0}, true, 10).rejected());
  EXPECT_FALSE(judge_reported_fit(fits, 1, 1, {}, true, 10).rejected());
}

TEST(FitRejection, TheResidualTrendsButNotNone) {
  for (const char* trend : {"falls-with-speed", "rises-with-speed", "runs"}) {
    const FitRejection r = judge_reported_fit({hertz(1.0, 0.0, trend)}, 0, 0, {}, true, 10);
    EXPECT_EQ(r.residual_trend, trend);
    EXPECT_TRUE(r.rejected());
  }
  for (const char* quiet : {"none", "n/a", ""}) {
    EXPECT_FALSE(judge_reported_fit({hertz(1.0, 0.0, quiet)}, 0, 0, {}, true, 10).rejected());
  }
}

TEST(FittedEps, TheBoundsSwapAndAnEdgeStaysAnEdge) {
  const double v = 2.0;
  const FitInterval ci68{0.1, 0.3, false, false};
  const FitInterval ci95{0.0, 0.5, false, true};  // no upper β bound: no lower ε bound
  const FittedEps e = fitted_eps_at_speed(0.2, ci68, ci95, CollisionEnd::naive, v);
  EXPECT_EQ(e.eps, fast::eps(zeta_from(0.2, v), CollisionEnd::naive));
  // ε falls with β: the larger β gives the lower ε.
  EXPECT_EQ(e.ci68.low, fast::eps(zeta_from(0.3, v), CollisionEnd::naive));
  EXPECT_EQ(e.ci68.high, fast::eps(zeta_from(0.1, v), CollisionEnd::naive));
  EXPECT_LT(e.ci68.low, e.eps);
  EXPECT_GT(e.ci68.high, e.eps);
  EXPECT_TRUE(e.ci95.low_at_edge);
  EXPECT_TRUE(std::isnan(e.ci95.low));
  EXPECT_EQ(e.ci95.high, fast::eps(0.0, CollisionEnd::naive));  // β = 0: elastic spheres
  EXPECT_GT(e.ci95.high, e.ci68.high);
}

TEST(FittedEps, ABoundBeyondTheCheckedRangeIsAtTheEdgeAndBetaItselfIsRefused) {
  const double v = 1.0;
  const FitInterval far{0.1, 2.0 * kLargestCheckedZeta, false, false};  // ζ = β at 1 m/s
  const FittedEps e = fitted_eps_at_speed(0.2, far, far, CollisionEnd::delayed_recovery, v);
  EXPECT_TRUE(e.ci68.low_at_edge);
  EXPECT_TRUE(std::isnan(e.ci68.low));
  EXPECT_FALSE(e.ci68.high_at_edge);
  EXPECT_THROW(fitted_eps_at_speed(2.0 * kLargestCheckedZeta, far, far, CollisionEnd::delayed_recovery, v),
               InvalidInput);
}

}  // namespace
