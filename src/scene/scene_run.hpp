#pragma once
// Running a planned scene: every job solved once (in parallel, one solver per thread), calibrations, and the
// comparisons the scene asks for. Results are values; writing them is the caller's business.
#include <cstddef>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "reference/work_precision.hpp"
#include "restitution/calibration.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"

namespace restitution::scene {

struct RunSettings {
  unsigned threads = 0;  // 0: one per hardware thread
  // Called after each finished collision with (done, total); never concurrently.
  std::function<void(std::size_t, std::size_t)> progress;
  // The reference solutions for [[work_precision]] studies (reference_file_in(source tree)); without one
  // those studies say so in their summary.
  std::filesystem::path reference_file;
};

// A column of an approximation evaluated on a sweep (a series, a Padé approximant), or why there is none.
struct ApproximationColumn {
  std::string label;   // column name, e.g. "series_delayed_recovery_20_terms"
  std::string source;  // what it is and where it comes from
  CollisionEnd end = CollisionEnd::naive;
  std::vector<double> eps;  // parallel to the sweep's points
};

struct PowerLawFitResult {
  CollisionEnd end = CollisionEnd::naive;
  double prefactor = 0.0, exponent = 0.0, exponent_uncertainty = 0.0;
  std::size_t points = 0;
};

struct SweepExtras {
  std::vector<ApproximationColumn> approximations;
  std::vector<PowerLawFitResult> fits;
  std::vector<double> empirical_eps;  // the empirical law at each velocity, when asked
  std::vector<std::string> notes;     // what was asked but is not available in this build, and why
};

struct CalibrationOutcome {
  Calibration calibration;
};

// A [[stability]] or [[work_precision]] study: summary lines for the report and, for work precision, the
// measured points.
struct StudyOutcome {
  std::vector<std::string> summary;
  std::vector<WorkPrecisionRow> work_precision;
};

struct SceneResults {
  Plan plan;
  std::vector<CollisionResult> solved;  // parallel to plan.jobs
  std::vector<SweepExtras> sweeps;      // parallel to Scene::sweeps
  std::vector<CalibrationOutcome> calibrations;
  std::vector<StudyOutcome> studies;  // parallel to Scene::studies
  SolverStats total;                  // summed over the planned collisions (not the calibrations)
  std::size_t collisions = 0;         // collisions integrated, calibrations included
};

// Runs `plan`, which plan_scene(scene) made: planning apart lets a caller refuse a scene (points outside the
// solver's range) before it prepares anything, without planning twice.
SceneResults run_scene(const Scene& scene, Plan plan, const RunSettings& settings = {});

// The result of a planned point (nullptr when the point needed no integration).
const CollisionResult* result_of(const SceneResults& results, const PlannedPoint& point);

}  // namespace restitution::scene
