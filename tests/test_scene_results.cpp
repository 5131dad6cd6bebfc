// SPDX-License-Identifier: BSD-3-Clause
// The typed results of a scene's studies (scene/scene_results.hpp) carry the numbers the report quotes: each
// is recomputed here independently from the solved collisions (or from closed forms written out in this
// file) and compared, so that the CLI, which only renders them, quotes numbers that were checked.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "analysis/stability_report.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"

namespace restitution::scene {
namespace {

SceneResults run(const Scene& s) {
  return run_scene(s, plan_scene(s));
}

double solved_eps(const SceneResults& r, const PlannedPoint& p, CollisionEnd end) {
  const CollisionResult* c = result_of(r, p);
  return c != nullptr && (*c)[end] ? (*c)[end]->eps : std::nan("");
}

// The dash-pot's ε written out from the exact solution x = e^{-rτ} sin(ωτ)/ω, ω = sqrt(1 - r²) (r < 1):
// the naive end at ωτ = π, the delayed-recovery end where 2r x' + x = 0, i.e. ωτ = atan2(2rω, 2r² - 1).
double dashpot_exact(double r, CollisionEnd end) {
  const double w = std::sqrt(1.0 - r * r);
  const double phase =
      end == CollisionEnd::naive ? std::numbers::pi : std::atan2(2.0 * r * w, 2.0 * r * r - 1.0);
  return std::exp(-r * phase / w);
}

TEST(SceneResults, DashpotErrorsAreTheClosedFormErrorsAndWithinTheTolerance) {
  const Scene s = parse_scene(
      "output = \"o\"\ntolerance = 1e-9\n[[dashpot]]\ndamping_ratio = [0.05, 0.3, 0.6, 0.9]\n", "t");
  const SceneResults r = run(s);
  ASSERT_EQ(outcomes_of<DashpotOutcome>(s, r, "dashpot").size(), 1U);
  const DashpotOutcome& d = *outcomes_of<DashpotOutcome>(s, r, "dashpot")[0];
  ASSERT_EQ(d.points.size(), 4U);
  for (const CollisionEnd end : {CollisionEnd::naive, CollisionEnd::delayed_recovery}) {
    double worst = 0.0;
    for (std::size_t i = 0; i < d.points.size(); ++i) {
      const double ratio = tasks_of<DashpotCheck>(s, "dashpot")[0]->damping_ratio[i];
      const auto& check = d.points[i].ends[end];
      ASSERT_TRUE(check.has_value());
      EXPECT_EQ(d.points[i].damping_ratio, ratio);
      EXPECT_EQ(check->eps, solved_eps(r, r.plan.points[0][i], end));
      const double exact = dashpot_exact(ratio, end);
      EXPECT_NEAR(check->eps_exact, exact, 4e-16);
      const double error = std::abs(check->eps - exact) / std::min(exact, 1.0 - exact);
      EXPECT_NEAR(check->relative_error, error, 1e-14);
      worst = std::max(worst, check->relative_error);
    }
    EXPECT_EQ(d.max_relative_error[end], worst);
    EXPECT_GT(d.max_relative_error[end], 0.0);
    EXPECT_LT(d.max_relative_error[end], s.tolerance);  // the accuracy contract, checked exactly
  }
}

TEST(SceneResults, DashpotWithoutANaiveEndHasNoCheckThere) {
  const Scene s = parse_scene("output = \"o\"\n[[dashpot]]\ndamping_ratio = [0.5, 2]\n", "t");
  const SceneResults r = run(s);
  const DashpotOutcome& d = *outcomes_of<DashpotOutcome>(s, r, "dashpot")[0];
  EXPECT_TRUE(d.points[0].ends[CollisionEnd::naive].has_value());
  EXPECT_FALSE(d.points[1].ends[CollisionEnd::naive].has_value());  // r >= 1: x never returns to 0
  EXPECT_TRUE(d.points[1].ends[CollisionEnd::delayed_recovery].has_value());
}

TEST(SceneResults, ApproximationDifferencesAndTheirWorstCaseAreRecomputable) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nzeta = [0.0, 0.05, 0.2, 5.0, 20.0]\n"
      "approximations = [\"naive-series\", \"pade-2011-3-6\"]\nasymptotics = true\n",
      "t");
  const SceneResults r = run(s);
  const auto& points = r.plan.points[0];
  const auto& columns = outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.approximations;
  ASSERT_EQ(columns.size(), 4U);  // two approximations, then the large-ζ laws of both ends
  EXPECT_TRUE(columns[0].approximation.has_value());
  EXPECT_FALSE(columns[2].approximation.has_value());
  EXPECT_EQ(columns[2].end, CollisionEnd::naive);
  EXPECT_GT(columns[2].kappa, 5.0);  // κ ≈ 5.158 (docs/asymptotics.md)
  for (const ApproximationColumn& c : columns) {
    SCOPED_TRACE(c.label);
    double worst = 0.0;
    std::size_t compared = 0;
    double lo = 1e300;
    double hi = -1.0;
    for (std::size_t i = 0; i < points.size(); ++i) {
      const double d = c.eps[i] / solved_eps(r, points[i], c.end) - 1.0;
      EXPECT_EQ(std::isfinite(d), std::isfinite(c.relative_difference[i]));
      if (!std::isfinite(d)) continue;
      EXPECT_EQ(c.relative_difference[i], d);
      worst = std::max(worst, std::abs(d));
      lo = std::min(lo, points[i].parameter);
      hi = std::max(hi, points[i].parameter);
      ++compared;
    }
    EXPECT_EQ(c.comparison.compared, compared);
    EXPECT_EQ(c.comparison.max_abs_relative_difference, worst);
    EXPECT_EQ(c.comparison.zeta_min, lo);
    EXPECT_EQ(c.comparison.zeta_max, hi);
  }
  // The large-ζ laws have no value at ζ = 0, so they are compared over the other four points.
  EXPECT_EQ(columns[2].comparison.compared, 4U);
  EXPECT_EQ(columns[2].comparison.zeta_min, 0.05);
  // The naive law at ζ = 20 agrees with the numerics to its own error (docs/asymptotics.md).
  EXPECT_LT(std::abs(columns[2].relative_difference[4]), 1e-9);
}

TEST(SceneResults, AnApproximationOfAnEndNotSolvedIsNotCompared) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nzeta = [0.1, 0.5]\nends = \"delayed-recovery\"\n"
      "approximations = [\"naive-series\"]\nfit = { zeta_min = 0.2 }\n",
      "t");
  const SceneResults r = run(s);
  const ApproximationColumn& c = outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.approximations[0];
  EXPECT_EQ(c.comparison.compared, 0U);
  EXPECT_TRUE(std::isnan(c.relative_difference[0]));
  // One point with ζ >= 0.2: no fit, and the shortfall says how many points there were.
  EXPECT_TRUE(outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.fits.empty());
  ASSERT_EQ(outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.fit_shortfalls.size(), 1U);
  EXPECT_EQ(outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.fit_shortfalls[0].end,
            CollisionEnd::delayed_recovery);
  EXPECT_EQ(outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.fit_shortfalls[0].points, 1U);
  EXPECT_EQ(outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.fit_shortfalls[0].zeta_min, 0.2);
}

TEST(SceneResults, EmpiricalDeviationIsTheLargestWhereTheLawIsACoefficient) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nbeta = 0.3\nvelocity = { from = 1e-5, to = 10, points = 13, spacing = "
      "\"log\" "
      "}\nends = \"naive\"\nempirical = { coefficient = 0.32, exponent = -0.234, velocity_unit = 0.01 }\n",
      "t");
  const SceneResults r = run(s);
  const SweepExtras& e = outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras;
  ASSERT_TRUE(e.empirical_deviation.has_value());
  double worst = 0.0;
  double at = 0.0;
  std::size_t skipped = 0;
  for (const PlannedPoint& p : r.plan.points[0]) {
    const double law = 0.32 * std::pow(*p.velocity_m_s / 0.01, -0.234);
    if (law >= 1.0) {
      ++skipped;
      continue;
    }
    const double d = std::abs(solved_eps(r, p, CollisionEnd::naive) / law - 1.0);
    if (d > worst) {
      worst = d;
      at = *p.velocity_m_s;
    }
  }
  EXPECT_GT(skipped, 0U);  // the slowest speeds, where the law exceeds 1, do not count
  EXPECT_EQ(e.empirical_deviation->end, CollisionEnd::naive);
  EXPECT_NEAR(e.empirical_deviation->max_relative_deviation, worst, 1e-15 * worst);
  EXPECT_EQ(e.empirical_deviation->at_velocity_m_s, at);
}

TEST(SceneResults, StabilitySummaryIsTheWorstOverTheReport) {
  const Scene s = parse_scene("output = \"o\"\ntolerance = 1e-8\n[[stability]]\nzeta = [0.5, 50]\n", "t");
  const SceneResults r = run(s);
  ASSERT_EQ(r.sections.size(), 1U);
  const auto& study = std::any_cast<const StudyOutcome&>(r.sections[0]);
  ASSERT_TRUE(study.stability.has_value());
  const StabilitySummary& summary = *study.stability;
  StabilityOptions options;
  options.tolerance = 1e-8;
  const StabilityReport report = stability_report({0.5, 50.0}, options);
  double self = 0.0;
  double engines = 0.0;
  for (const StabilityPoint& p : report.points) {
    self = std::max(self, p.self_convergence);
    for (const EngineCheck& c : p.engines) {
      if (c.solved) engines = std::max(engines, c.relative_difference);
    }
  }
  EXPECT_EQ(summary.tolerance, 1e-8);
  EXPECT_EQ(summary.pairs, 4U);
  EXPECT_EQ(summary.flagged, report.flagged());
  EXPECT_EQ(summary.worst_self_convergence, self);
  EXPECT_EQ(summary.worst_engine_difference, engines);
  EXPECT_LT(summary.worst_engine_difference, 1e-8);
}

}  // namespace
}  // namespace restitution::scene
