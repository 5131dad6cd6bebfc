// SPDX-License-Identifier: BSD-3-Clause
// The damping check over a grid (damping_check/grid.hpp), which a scene's [[damping_check]] section renders:
// every value is the one check_recipe gives for that recipe, requested ε, clamp and speed, and the relative
// errors are (actual - requested) / requested of those values.
#include <gtest/gtest.h>

#include <cmath>

#include "damping_check/grid.hpp"

namespace restitution::damping_check {
namespace {

double actual(Recipe recipe, double eps, Clamp clamp, double speed, double v_ref, CollisionSolver& solver) {
  CheckRequest request;
  request.recipe = recipe;
  request.eps_requested = eps;
  request.clamps = {clamp};
  request.reference_velocity_m_s = v_ref;
  request.speeds_m_s = {speed};
  request.tolerance = 1e-9;
  return check_recipe(request, solver).points.front().actual_eps.value_or(std::nan(""));
}

TEST(DampingGrid, ValuesAreTheRecipeChecksAndErrorsTheirRelativeDifferences) {
  CollisionSolver solver;
  GridRequest g;
  g.recipes = {Recipe::lammps_tsuji, Recipe::lammps_viscoelastic};
  g.eps = {0.2, 0.7};
  g.reference_velocity_m_s = 2.0;
  g.speeds_m_s = {0.5, 8.0};
  g.tolerance = 1e-9;
  const GridResult r = check_grid(g, solver);
  EXPECT_EQ(r.findings_speeds_m_s[0], 0.2);
  EXPECT_EQ(r.findings_speeds_m_s[2], 20.0);
  ASSERT_EQ(r.recipes.size(), 2U);
  const RecipeGrid& tsuji = r.recipes[0];
  const RecipeGrid& visco = r.recipes[1];
  EXPECT_TRUE(tsuji.speed_independent);
  EXPECT_TRUE(tsuji.speed_dependence.empty());
  ASSERT_EQ(tsuji.recipe_error_at_calibration_speed.size(), 2U);
  EXPECT_FALSE(visco.speed_independent);
  ASSERT_EQ(visco.speed_dependence.size(), 2U);
  for (std::size_t k = 0; k < g.eps.size(); ++k) {
    const double e = g.eps[k];
    EXPECT_EQ(tsuji.at_reference[k].on.front(), actual(Recipe::lammps_tsuji, e, Clamp::on, 2.0, 2.0, solver));
    EXPECT_EQ(visco.at_reference[k].off.front(),
              actual(Recipe::lammps_viscoelastic, e, Clamp::off, 2.0, 2.0, solver));
    for (std::size_t i = 0; i < g.speeds_m_s.size(); ++i) {
      const double a = actual(Recipe::lammps_viscoelastic, e, Clamp::on, g.speeds_m_s[i], 2.0, solver);
      const double at_ref = visco.at_reference[k].on.front();
      EXPECT_EQ(visco.speed_dependence[k].on[i], a / at_ref - 1.0);
      // The two parts multiply back to the total error against the request.
      EXPECT_NEAR((1.0 + visco.recipe_error_at_calibration_speed[k].on.front()) *
                      (1.0 + visco.speed_dependence[k].on[i]),
                  a / e, 1e-14);
    }
    EXPECT_EQ(tsuji.recipe_error_at_calibration_speed[k].on.front(),
              tsuji.at_reference[k].on.front() / e - 1.0);
    // Calibrated at v_ref for the delayed-recovery end: exact there with the clamp (to the tolerance).
    EXPECT_NEAR(visco.at_reference[k].on.front(), e, 1e-8);
  }
  ASSERT_EQ(visco.findings.size(), kFindingsEps.size());
  EXPECT_EQ(visco.findings[1].on.size(), 3U);  // at v_ref/10, v_ref, 10 v_ref
  EXPECT_EQ(tsuji.findings[1].on.size(), 1U);  // speed-independent: one value
  EXPECT_EQ(visco.findings[1].on[2], actual(Recipe::lammps_viscoelastic, 0.5, Clamp::on, 20.0, 2.0, solver));
}

}  // namespace
}  // namespace restitution::damping_check
