// SPDX-License-Identifier: BSD-3-Clause
// Planning and running scenes: the work follows from what is asked. Checked through the solver statistics
// against direct solves: one solve per distinct collision, no naive tail unless asked, no trajectory unless
// asked; physical points use ζ = β v^{1/5}.
#include <gtest/gtest.h>

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "reference/work_precision.hpp"
#include "restitution/errors.hpp"
#include "restitution/series.hpp"
#include "restitution/units.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_run.hpp"
#include "scene/scene_sections.hpp"
#include "scene/scene_studies.hpp"

namespace restitution::scene {
namespace {

CollisionResult direct(double zeta, EndSet ends, bool trajectory) {
  CollisionSolver solver;
  SolveOptions o;
  o.ends = ends;
  o.keep_trajectory = trajectory;
  return solver.solve(ContactLaw::hertz_natural(zeta), o);
}

void expect_same_stats(const SolverStats& a, const SolverStats& b) {
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.rhs_evaluations, b.rhs_evaluations);
  EXPECT_EQ(a.root_evaluations, b.root_evaluations);
}

TEST(SceneRun, DelayedRecoveryOnlyNeverIntegratesTheNaiveTail) {
  const Scene s =
      parse_scene("output = \"o\"\n[[sweep]]\nzeta = [0.5, 3]\nends = \"delayed-recovery\"\n", "t");
  const SceneResults r = run_scene(s, plan_scene(s));
  ASSERT_EQ(r.solved.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    const double zeta = tasks_of<Sweep>(s, "sweep")[0]->zeta[i];
    EXPECT_FALSE(r.solved[i][CollisionEnd::naive].has_value());
    ASSERT_TRUE(r.solved[i][CollisionEnd::delayed_recovery].has_value());
    EXPECT_TRUE(r.solved[i].trajectory.empty());
    expect_same_stats(r.solved[i].stats, direct(zeta, EndSet{CollisionEnd::delayed_recovery}, false).stats);
    // Going on to the naive end costs more steps: the scene did not pay for them.
    EXPECT_LT(r.solved[i].stats.steps, direct(zeta, EndSet::both(), false).stats.steps);
  }
}

TEST(SceneRun, OneSolveIsSharedByEveryOutputThatNeedsIt) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nname = \"a\"\nzeta = [0.5, 1]\nends = \"naive\"\n"
      "[[sweep]]\nname = \"b\"\nzeta = [1]\nends = \"delayed-recovery\"\n"
      "[[trajectory]]\nzeta = 0.5\nends = \"delayed-recovery\"\n",
      "t");
  const SceneResults r = run_scene(s, plan_scene(s));
  ASSERT_EQ(r.plan.jobs.size(), 2U);            // ζ = 0.5 and ζ = 1, each once
  ASSERT_EQ(s.sections[2].kind, "trajectory");  // the table's order: the sweeps, then the trajectory
  EXPECT_EQ(r.plan.points[1][0].job, r.plan.points[0][1].job);
  EXPECT_EQ(r.plan.points[2][0].job, r.plan.points[0][0].job);
  const CollisionResult& half = r.solved[r.plan.points[0][0].job];
  expect_same_stats(half.stats, direct(0.5, EndSet::both(), true).stats);
  EXPECT_FALSE(half.trajectory.empty());
  const CollisionResult& one = r.solved[r.plan.points[0][1].job];
  expect_same_stats(one.stats, direct(1.0, EndSet::both(), false).stats);
  EXPECT_TRUE(one.trajectory.empty());
  // The total is the field-by-field sum (SolverStats operator+=).
  EXPECT_EQ(r.total.steps, half.stats.steps + one.stats.steps);
  EXPECT_EQ(r.total.rhs_evaluations, half.stats.rhs_evaluations + one.stats.rhs_evaluations);
  EXPECT_EQ(r.total.jacobian_evaluations, half.stats.jacobian_evaluations + one.stats.jacobian_evaluations);
  EXPECT_EQ(r.total.root_evaluations, half.stats.root_evaluations + one.stats.root_evaluations);
  EXPECT_EQ(r.total.error_test_failures, half.stats.error_test_failures + one.stats.error_test_failures);
  EXPECT_EQ(r.total.convergence_failures, half.stats.convergence_failures + one.stats.convergence_failures);
  EXPECT_EQ(r.collisions, 2U);
}

TEST(SceneRun, PhysicalSweepsUseZetaFromBetaAndVelocity) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nbeta = 0.2\nvelocity = [1, 32]\n"
      "[[sweep]]\ncharacteristic_velocity = 0.0032\nvelocity = [0.01]\nends = \"naive\"\n",
      "t");
  const Plan p = plan_scene(s);
  EXPECT_DOUBLE_EQ(p.points[0][0].parameter, 0.2);
  EXPECT_NEAR(p.points[0][1].parameter, 0.4, 1e-15);
  // 1999 paper: (g/g*)^{1/5} = C1 ζ.
  EXPECT_NEAR(series::c1_closed_form() * p.points[1][0].parameter, std::pow(0.01 / 0.0032, 0.2), 1e-14);
  const Scene far = parse_scene("output = \"o\"\n[[sweep]]\nbeta = 100\nvelocity = [1e30]\n", "t");
  EXPECT_THROW((void)plan_scene(far), InvalidInput);
}

// Issue 12, item 18: a calibrated material without damping gives the same A as with any damping given.
TEST(SceneRun, CalibrationIgnoresAndNeedsNoDampingOfTheMaterial) {
  const std::string material =
      "output = \"o\"\n[materials.ice]\nyoung_modulus = 7e9\npoisson_ratio = 0.3\ndensity = 917\n"
      "radius = 0.01\n";
  const std::string task = "[[calibration]]\neps = 0.8\nvelocity = 1\nmaterial = \"ice\"\n";
  const Scene bare = parse_scene(material + task, "t");
  const Scene damped = parse_scene(material + "dissipative_constant = 3e-4\n" + task, "t");
  const SceneResults a = run_scene(bare, plan_scene(bare));
  const SceneResults b = run_scene(damped, plan_scene(damped));
  ASSERT_TRUE(outcomes_of<CalibrationOutcome>(bare, a, "calibration")[0]
                  ->calibration.dissipative_constant_s.has_value());
  EXPECT_EQ(
      *outcomes_of<CalibrationOutcome>(bare, a, "calibration")[0]->calibration.dissipative_constant_s,
      *outcomes_of<CalibrationOutcome>(damped, b, "calibration")[0]->calibration.dissipative_constant_s);
  EXPECT_NEAR(outcomes_of<CalibrationOutcome>(bare, a, "calibration")[0]->calibration.eps_at_zeta, 0.8, 1e-9);
}

TEST(SceneRun, ApproximationsAreEvaluatedBesideTheNumerics) {
  const Scene s = parse_scene(
      "output = \"o\"\n[[sweep]]\nzeta = [0.01, 20]\nends = \"naive\"\n"
      "approximations = [\"naive-series\", \"pade-1999\"]\nasymptotics = true\n",
      "t");
  const SceneResults r = run_scene(s, plan_scene(s));
  const auto& columns = outcomes_of<SweepOutcome>(s, r, "sweep")[0]->extras.approximations;
  ASSERT_EQ(columns.size(), 3U);  // two approximations and the naive large-ζ law
  const double eps_small = r.solved[r.plan.points[0][0].job][CollisionEnd::naive]->eps;
  EXPECT_NEAR(columns[0].eps[0] / eps_small, 1.0, 1e-10);  // the series at ζ = 0.01
  EXPECT_NEAR(columns[1].eps[0] / eps_small, 1.0, 1e-6);   // the Padé agrees with the series at small ζ
  const double eps_large = r.solved[r.plan.points[0][1].job][CollisionEnd::naive]->eps;
  EXPECT_NEAR(columns[2].eps[1] / eps_large, 1.0, 1e-9);  // κ ζ^{-5} at ζ = 20
  EXPECT_THROW((void)parse_scene("output = \"o\"\n[[sweep]]\nzeta = 1\napproximations = [\"taylor\"]\n", "t"),
               InvalidInput);
}

TEST(SceneRun, DashpotPointsWithoutANaiveEndAreNotIntegratedForIt) {
  const Scene s =
      parse_scene("output = \"o\"\n[[dashpot]]\ndamping_ratio = [0.5, 2]\nends = \"naive\"\n", "t");
  const SceneResults r = run_scene(s, plan_scene(s));
  EXPECT_EQ(r.plan.jobs.size(), 1U);
  EXPECT_EQ(r.plan.points[0][1].job, kNoJob);
  EXPECT_EQ(result_of(r, r.plan.points[0][1]), nullptr);
}

TEST(SceneRun, ResultsDoNotDependOnTheNumberOfThreads) {
  const Scene s = parse_scene("output = \"o\"\n[[sweep]]\nzeta = {from = 0.1, to = 50, points = 12}\n", "t");
  RunSettings one;
  one.threads = 1;
  RunSettings three;
  three.threads = 3;
  std::size_t calls = 0;
  three.progress = [&calls](std::size_t done, std::size_t total) {
    ++calls;
    EXPECT_LE(done, total);
  };
  const SceneResults a = run_scene(s, plan_scene(s), one);
  const SceneResults b = run_scene(s, plan_scene(s), three);
  EXPECT_EQ(calls, 12U);
  for (std::size_t i = 0; i < a.solved.size(); ++i) {
    EXPECT_EQ(a.solved[i][CollisionEnd::naive]->eps, b.solved[i][CollisionEnd::naive]->eps);
    EXPECT_EQ(a.solved[i][CollisionEnd::delayed_recovery]->eps,
              b.solved[i][CollisionEnd::delayed_recovery]->eps);
  }
}

TEST(SceneRun, WorkPrecisionStudyMeasuresAgainstTheReferenceAndSummarises) {
  Scene s = parse_scene(
      "output = \"o\"\n[[work_precision]]\nname = \"wp\"\nengines = [\"taylor\", \"bdf\"]\nrepeats = 2\n",
      "t");
  make_quick(s, 6);
  EXPECT_EQ(tasks_of<ExternalStudy>(s, "work_precision")[0]->repeats, 1);
  RunSettings settings;
  settings.reference_file = reference_file_in(RESTITUTION_SOURCE_DIR);
  const SceneResults r = run_scene(s, plan_scene(s), settings);
  ASSERT_EQ(r.sections.size(), 1U);
  const auto& study = std::any_cast<const StudyOutcome&>(r.sections[0]);
  // The same points as the work-precision module measures on its own (timings aside).
  const auto direct =
      measure_work_precision(read_reference_file(settings.reference_file), 1, {"taylor", "bdf"});
  ASSERT_EQ(study.work_precision.size(), direct.size());
  for (std::size_t i = 0; i < direct.size(); ++i) {
    EXPECT_EQ(study.work_precision[i].zeta, direct[i].zeta);
    EXPECT_EQ(study.work_precision[i].error, direct[i].error);
  }
  EXPECT_EQ(study.gap, StudyGap::none);
  EXPECT_EQ(study.reference_file, settings.reference_file);
  // One highlight per engine and end, whose best error is the smallest worst-over-ζ error of the ladder and
  // whose quoted group is the one at 1e-10.
  ASSERT_EQ(study.work_precision_highlights.size(), 4U);
  for (const WorkPrecisionHighlight& h : study.work_precision_highlights) {
    SCOPED_TRACE(h.best.engine + " " + h.best.end);
    EXPECT_EQ(h.quoted.engine, h.best.engine);
    EXPECT_EQ(h.quoted.end, h.best.end);
    double best = 1.0;
    for (const double tolerance : work_precision_tolerances()) {
      double worst = -1.0;
      for (const WorkPrecisionRow& row : direct) {
        if (row.engine == h.best.engine && row.end == h.best.end && row.tolerance == tolerance)
          worst = std::max(worst, row.error);
      }
      if (worst >= 0.0) best = std::min(best, worst);
      if (tolerance == kQuotedTolerance) EXPECT_EQ(h.quoted.max_error, worst);
    }
    EXPECT_EQ(h.best.max_error, best);
    EXPECT_EQ(h.quoted.tolerance, kQuotedTolerance);
  }
}

TEST(SceneRun, StudiesWithoutInputSayWhy) {
  const Scene s = parse_scene("output = \"o\"\n[[work_precision]]\nname = \"wp\"\n", "t");
  const SceneResults r = run_scene(s, plan_scene(s));  // no reference file in the settings
  ASSERT_EQ(r.sections.size(), 1U);
  const auto& study = std::any_cast<const StudyOutcome&>(r.sections[0]);
  EXPECT_EQ(study.gap, StudyGap::no_reference_file);
  EXPECT_TRUE(study.work_precision.empty());
}

TEST(SceneRun, WorkPrecisionStudyRejectsUnknownEnginesAndBadRepeats) {
  EXPECT_THROW(parse_scene("output = \"o\"\n[[work_precision]]\nengines = [\"rk4\"]\n", "t"), InvalidInput);
  EXPECT_THROW(parse_scene("output = \"o\"\n[[work_precision]]\nrepeats = 0\n", "t"), InvalidInput);
  EXPECT_THROW(parse_scene("output = \"o\"\n[[work_precision]]\nrepeats = 1.5\n", "t"), InvalidInput);
  EXPECT_THROW(parse_scene("output = \"o\"\n[[work_precision]]\nzeta = [1]\n", "t"), InvalidInput);
}

}  // namespace
}  // namespace restitution::scene
