// SPDX-License-Identifier: BSD-3-Clause
// An ε(v) sweep's grid (sweep/velocity_sweep.hpp): ζ = β v^{1/5} with the material's natural scales, the
// dash-pot's speed-independent ζ = γ/sqrt(k m) from its physical coefficients, and a speed whose ζ is beyond
// the checked range refused by name.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "restitution/errors.hpp"
#include "sweep/velocity_sweep.hpp"

namespace {

using namespace restitution;

TEST(VelocitySweep, BetaGivesZetaFromTheFifthRootOfTheSpeed) {
  const std::vector<double> speeds{0.01, 1.0, 32.0};
  const VelocitySweep s =
      velocity_sweep(LawKind::viscoelastic_hertz, {0.3, std::nullopt, std::nullopt}, speeds);
  ASSERT_EQ(s.zetas.size(), 3U);
  EXPECT_DOUBLE_EQ(s.zetas[1], 0.3);
  EXPECT_NEAR(s.zetas[2], 0.6, 1e-15);  // 32^{1/5} = 2
  EXPECT_NEAR(s.zetas[0], 0.3 * std::pow(0.01, 0.2), 1e-15);
  EXPECT_EQ(s.columns.velocity_m_s, speeds);
  EXPECT_EQ(s.columns.beta, 0.3);
  EXPECT_TRUE(s.columns.scales.empty());
}

TEST(VelocitySweep, AMaterialsStiffnessGivesTheNaturalScales) {
  const double k = 4e5;
  const VelocitySweep s = velocity_sweep(LawKind::viscoelastic_hertz, {0.3, k, std::nullopt}, {0.5, 2.0});
  ASSERT_EQ(s.columns.scales.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    const double v = s.columns.velocity_m_s[i];
    EXPECT_NEAR(s.columns.scales[i].time_s, std::pow(k, -0.4) * std::pow(v, -0.2), 1e-15);
    // L = v T: x'(0) = 1 in natural units.
    EXPECT_NEAR(s.columns.scales[i].length_m / s.columns.scales[i].time_s, v, 1e-12 * v);
  }
}

TEST(VelocitySweep, TheDashpotsZetaDoesNotDependOnTheSpeed) {
  const PhysicalCoefficients c{1e4, 2.0, 0.01};  // k [N/m], γ [N s/m], m [kg]
  const VelocitySweep s =
      velocity_sweep(LawKind::linear_dashpot, {std::nullopt, std::nullopt, c}, {0.1, 1.0, 10.0});
  for (const double zeta : s.zetas) EXPECT_NEAR(zeta, 2.0 / std::sqrt(1e4 * 0.01), 1e-14);
  EXPECT_FALSE(s.columns.beta.has_value());
  EXPECT_EQ(s.columns.scales.size(), 3U);
}

TEST(VelocitySweep, AZetaBeyondTheCheckedRangeIsRefusedNamingTheSpeed) {
  // β = 1: ζ = v^{1/5} > 1e6 from v = 1e30 m/s on.
  try {
    velocity_sweep(LawKind::viscoelastic_hertz, {1.0, std::nullopt, std::nullopt}, {1.0, 1e31});
    FAIL() << "zeta = 1.58e6 is outside the checked range";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("velocity 1e+31 m/s with beta 1"), std::string::npos) << e.what();
  }
}

}  // namespace
