// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a scene's studies found, as typed values: approximation columns and their comparison with the
// numerics, power-law fits, the empirical-law deviation, dash-pot closed-form checks, stability and
// work-precision summaries. The library computes every number here; the CLI only renders them (report.md,
// CSV, JSON, plots), so no prose is built and no figure is computed outside this module.
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "reference/work_precision.hpp"
#include "restitution/calibration.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/series.hpp"
#include "scene/scene_plan.hpp"

namespace restitution::scene {

// How an approximation compares with the numerics over a sweep: the largest |relative difference| over the
// points where both exist (none compared: compared == 0, e.g. a naive-end law on a delayed-recovery sweep).
struct ApproximationComparison {
  std::size_t compared = 0;
  double max_abs_relative_difference = 0.0;
  double zeta_min = 0.0, zeta_max = 0.0;  // the range of the compared points
};

// A column of an approximation evaluated on a sweep: a catalogued approximation (a series, a Padé
// approximant) or, without one, the derived large-ζ law of `end` (docs/asymptotics.md).
struct ApproximationColumn {
  std::string label;                                   // column name, e.g. "series_delayed_recovery_20_terms"
  std::optional<series::Approximation> approximation;  // empty: the derived large-ζ law
  double kappa = 0.0;  // the naive large-ζ law's prefactor, ε = κ ζ^{-5} (naive law column only)
  CollisionEnd end = CollisionEnd::naive;
  std::vector<double> eps;  // parallel to the sweep's points
  // eps / ε - 1 against the numerics at `end`, NaN where that end was not solved; parallel to the points.
  std::vector<double> relative_difference;
  ApproximationComparison comparison;
};

struct PowerLawFitResult {
  CollisionEnd end = CollisionEnd::naive;
  double prefactor = 0.0, exponent = 0.0, exponent_uncertainty = 0.0;
  std::size_t points = 0;
};

// A fit that was asked for but has too few points (fewer than kMinFitPoints with ζ >= zeta_min).
struct FitShortfall {
  CollisionEnd end = CollisionEnd::naive;
  std::size_t points = 0;
  double zeta_min = 0.0;
};
inline constexpr std::size_t kMinFitPoints = 3;

// The largest relative deviation |ε / ε_empirical - 1| of the computed ε at `end` (naive when solved) where
// the empirical law is a valid coefficient (< 1), and the impact speed where it occurs.
struct EmpiricalDeviation {
  CollisionEnd end = CollisionEnd::naive;
  double max_relative_deviation = 0.0;
  double at_velocity_m_s = 0.0;
};

struct SweepExtras {
  std::vector<ApproximationColumn> approximations;
  std::vector<PowerLawFitResult> fits;
  std::vector<FitShortfall> fit_shortfalls;
  std::vector<double> empirical_eps;  // the empirical law at each velocity, when asked
  std::optional<EmpiricalDeviation> empirical_deviation;
};

// A [[sweep]]: its points in the shared plan, each one's solved collision, and the studies it asks for.
struct SweepOutcome {
  std::vector<PlannedPoint> points;
  std::vector<CollisionResult> results;  // parallel to points (a sweep's every point is integrated)
  SweepExtras extras;
};

// A [[trajectory]]: its collision in the shared plan, solved with its trajectory (which may run past the
// section's ends when another section asked for more of the same collision).
struct TrajectoryOutcome {
  PlannedPoint point;
  CollisionResult result;
};

// A dash-pot point at one end against the closed form (reference/dashpot_closed_form.hpp): the error is
// |ε - ε_exact| / min(ε_exact, 1 - ε_exact), which the scene's tolerance bounds.
struct DashpotEndCheck {
  double eps = 0.0, eps_exact = 0.0, relative_error = 0.0;
};

struct DashpotPoint {
  double damping_ratio = 0.0;
  PerEnd<std::optional<DashpotEndCheck>> ends;  // empty where the end was not asked for or does not exist
};

struct DashpotOutcome {
  std::vector<DashpotPoint> points;   // parallel to the plan's dash-pot points
  PerEnd<double> max_relative_error;  // over the points that have the end (0 when none)
};

struct CalibrationOutcome {
  Calibration calibration;
};

// The figures of a stability study (stability_report.hpp) over its point-end pairs; differences are
// relative to min(ε, 1 - ε).
struct StabilitySummary {
  double tolerance = 0.0;  // the one the study ran at
  std::size_t pairs = 0;
  int flagged = 0;
  double worst_self_convergence = 0.0;
  double worst_engine_difference = 0.0;  // over the engines that produced a result
};

// Per engine and end of a work-precision study: the group (tolerance) with the best worst-over-ζ error, and
// the one at kQuotedTolerance (or the tightest the engine accepts, when that is looser).
struct WorkPrecisionHighlight {
  WorkPrecisionGroup best;
  WorkPrecisionGroup quoted;
};
inline constexpr double kQuotedTolerance = SolveOptions{}.tolerance;  // the default

// Why a study has no result.
enum class StudyGap { none, no_reference_file, no_zeta_values };

// A [[stability]] or [[work_precision]] study (parallel to Scene::studies).
struct StudyOutcome {
  StudyGap gap = StudyGap::none;
  std::optional<StabilitySummary> stability;
  std::filesystem::path reference_file;          // work precision: what it was measured against
  std::vector<WorkPrecisionRow> work_precision;  // work precision: the measured points
  std::vector<WorkPrecisionHighlight> work_precision_highlights;  // in group_work_precision's order
};

}  // namespace restitution::scene
