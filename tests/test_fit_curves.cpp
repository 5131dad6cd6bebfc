// SPDX-License-Identifier: BSD-3-Clause
// The curves fit-data draws (fit/fit_curves.hpp): one per converged fit, over the data's speeds, the 95 %
// band around the best curve, flat for the speed-independent laws, falling with the speed for viscoelastic
// Hertz, and at the data's slowest and fastest speed the model ε the fit itself computed there.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "fit/fit_curves.hpp"
#include "restitution/fit.hpp"

namespace {

using namespace restitution;

FitData drop_data() {
  FitData d;
  d.velocity_m_s = {0.2, 0.2, 0.5, 0.5, 1.0, 1.0, 2.0, 2.0, 5.0, 5.0};
  d.eps = {0.8472, 0.8549, 0.8212, 0.8203, 0.7917, 0.7988, 0.7874, 0.7805, 0.7504, 0.7425};
  d.sigma.assign(d.eps.size(), 0.01);
  return d;
}

TEST(FitCurves, OnePerConvergedFitWithItsBandAroundIt) {
  const FitData d = drop_data();
  const FitOptions options;
  const FitResult r = fit_data(d, options);
  const FitCurves c = fit_curves(d, r, options);
  ASSERT_EQ(c.velocity_m_s.size(), static_cast<std::size_t>(kFitCurvePoints));
  EXPECT_EQ(c.velocity_m_s.front(), 0.2);
  EXPECT_NEAR(c.velocity_m_s.back(), 5.0, 1e-14);
  EXPECT_TRUE(std::is_sorted(c.velocity_m_s.begin(), c.velocity_m_s.end()));
  const auto converged = std::count_if(r.fits.begin(), r.fits.end(),
                                       [](const LawFit& f) { return f.status == FitStatus::converged; });
  ASSERT_EQ(static_cast<long>(c.curves.size()), converged);
  for (const FitCurve& curve : c.curves) {
    const LawFit& f = r.fits.at(curve.fit);
    ASSERT_EQ(f.status, FitStatus::converged);
    ASSERT_EQ(curve.eps.size(), c.velocity_m_s.size());
    for (std::size_t k = 0; k < curve.eps.size(); ++k) {
      if (!std::isnan(curve.band_low[k])) EXPECT_LE(curve.band_low[k], curve.eps[k]);
      if (!std::isnan(curve.band_high[k])) EXPECT_GE(curve.band_high[k], curve.eps[k]);
      if (speed_independent(f.candidate.law)) {
        EXPECT_EQ(curve.eps[k], curve.eps.front());
      } else if (k > 0) {
        EXPECT_LT(curve.eps[k], curve.eps[k - 1]);
      }
    }
    // The first data point is at the slowest speed, the last at the fastest: the fit's own model ε there.
    EXPECT_NEAR(curve.eps.front(), f.model_eps.front(), 1e-9);
    EXPECT_NEAR(curve.eps.back(), f.model_eps.back(), 1e-9);
  }
}

}  // namespace
