// SPDX-License-Identifier: BSD-3-Clause
// One adhesive contact over impact speeds (adhesion/adhesive_study.hpp): elastic JKR sticks below
// v_s = sqrt(2W/m*) and bounces above with ε = sqrt(1 − W/(½m*v²)), each collision is the single solve at its
// speed, and the stuck ones are counted.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "adhesion/adhesive_study.hpp"

namespace {

using namespace restitution;

// µm water ice (docs/adhesion.md §7): Y = 7 GPa, ν = 0.25, ρ = 920 kg/m³, R = 1.5 µm, γ = 0.19 J/m²,
// undamped.
AdhesiveContact elastic_ice() {
  const double young = 7e9, poisson = 0.25, radius = 1.5e-6;
  const double mass = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * 920.0;
  return {AdhesiveModel::jkr, young / (2.0 * (1.0 - poisson * poisson)), radius / 2.0, mass / 2.0, 0.19, 0.0};
}

TEST(AdhesiveStudy, ElasticJkrSticksBelowTheClosedFormSpeed) {
  const AdhesiveContact c = elastic_ice();
  const double work = elastic_hysteresis_work_j(c);
  const double v_s = std::sqrt(2.0 * work / c.effective_mass_kg);
  const std::vector<double> speeds{0.5 * v_s, 0.9 * v_s, 1.5 * v_s, 3.0 * v_s};
  const AdhesiveStudy s = study_adhesive_contact(c, speeds, 1e-10);
  EXPECT_EQ(s.elastic_hysteresis_work_j, work);
  EXPECT_EQ(s.break_overlap_m, break_overlap_m(c));
  EXPECT_NEAR(s.sticking.speed_m_per_s / v_s, 1.0, 1e-12);
  ASSERT_EQ(s.collisions.size(), speeds.size());
  EXPECT_EQ(s.stuck, 2U);
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const AdhesiveCollision one = solve_adhesive(c, speeds[i], 1e-10);
    EXPECT_EQ(s.collisions[i].outcome, one.outcome);
    EXPECT_EQ(s.collisions[i].eps, one.eps);
  }
  const double v = speeds[3];
  EXPECT_NEAR(s.collisions[3].eps, std::sqrt(1.0 - work / (0.5 * c.effective_mass_kg * v * v)), 1e-9);
}

TEST(AdhesiveStudy, NoSpeedsStillGivesTheStickingSpeed) {
  const AdhesiveStudy s = study_adhesive_contact(elastic_ice(), {}, 1e-10);
  EXPECT_TRUE(s.collisions.empty());
  EXPECT_EQ(s.stuck, 0U);
  EXPECT_GT(s.sticking.speed_m_per_s, 0.0);
}

}  // namespace
