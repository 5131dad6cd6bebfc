// SPDX-License-Identifier: BSD-3-Clause
// Calibration of fit_data's intervals: over many synthetic data sets with Gaussian noise (fixed seed) the
// 95 % interval must cover the true β in 95 % ± 2 % of them and the 68 % interval in 68 % ± 3 %, with σ
// known (Δχ² = 1, 3.84) and with σ estimated from the residuals (t quantiles, few points).
#include <gtest/gtest.h>

#include <cstdio>
#include <random>
#include <vector>

#include "restitution/fast.hpp"
#include "restitution/fit.hpp"
#include "restitution/units.hpp"

namespace restitution {
namespace {

struct Coverage {
  int sets = 0;
  int covered68 = 0;
  int covered95 = 0;
};

Coverage coverage(CollisionEnd end, double beta, const std::vector<double>& speeds, double sigma,
                  bool sigma_known, int sets, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  FitOptions options;
  options.candidates = {{LawKind::viscoelastic_hertz, end}};
  Coverage c;
  for (int s = 0; s < sets; ++s) {
    FitData d;
    for (const double v : speeds) {
      d.velocity_m_s.push_back(v);
      d.eps.push_back(fast::eps(zeta_from(beta, v), end) + noise(random));
      if (sigma_known) d.sigma.push_back(sigma);
    }
    const LawFit f = fit_data(d, options).fits.front();
    EXPECT_EQ(f.status, FitStatus::converged) << f.message;
    ++c.sets;
    c.covered68 += static_cast<int>(f.ci68.low <= beta && beta <= f.ci68.high);
    c.covered95 += static_cast<int>(f.ci95.low <= beta && beta <= f.ci95.high);
  }
  return c;
}

void check(const char* label, const Coverage& c) {
  const double p68 = static_cast<double>(c.covered68) / c.sets;
  const double p95 = static_cast<double>(c.covered95) / c.sets;
  std::printf("%-52s %d sets: 68%% interval covers %.2f %%, 95%% interval covers %.2f %%\n", label, c.sets,
              100 * p68, 100 * p95);
  EXPECT_NEAR(p68, 0.68, 0.03) << label;
  EXPECT_NEAR(p95, 0.95, 0.02) << label;
}

const std::vector<double> kTenSpeeds{0.05, 0.1, 0.2, 0.4, 0.7, 1.0, 1.5, 2.0, 3.0, 5.0};
const std::vector<double> kFourSpeeds{0.1, 0.5, 1.5, 4.0};

TEST(FitDataCoverage, KnownSigmaDelayedRecovery) {
  check("delayed recovery, beta 0.2, 10 points, sigma 0.01 known",
        coverage(CollisionEnd::delayed_recovery, 0.2, kTenSpeeds, 0.01, true, 2000, 1));
}

TEST(FitDataCoverage, KnownSigmaNaive) {
  check("naive, beta 1, 10 points, sigma 0.02 known",
        coverage(CollisionEnd::naive, 1.0, kTenSpeeds, 0.02, true, 2000, 2));
}

TEST(FitDataCoverage, EstimatedSigmaFewPointsUsesTQuantiles) {
  check("delayed recovery, beta 0.2, 4 points, sigma 0.01 estimated",
        coverage(CollisionEnd::delayed_recovery, 0.2, kFourSpeeds, 0.01, false, 2000, 3));
}

TEST(FitDataCoverage, EstimatedSigmaNaive) {
  check("naive, beta 1, 10 points, sigma 0.02 estimated",
        coverage(CollisionEnd::naive, 1.0, kTenSpeeds, 0.02, false, 2000, 4));
}

}  // namespace
}  // namespace restitution
