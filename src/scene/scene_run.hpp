// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Running a planned scene: every job solved once (in parallel, one solver per thread), then every section
// through its row (scene_sections.hpp): the comparisons of the planner's sections, calibrations, the others.
// Results are values; writing them is the caller's business.
#include <any>
#include <cstddef>
#include <filesystem>
#include <functional>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_results.hpp"

namespace restitution::scene {

struct RunSettings {
  unsigned threads = 0;  // 0: one per hardware thread
  // Called after each finished collision with (done, total); never concurrently.
  std::function<void(std::size_t, std::size_t)> progress;
  // The reference solutions for [[work_precision]] studies (reference_file_in(source tree)); without one
  // those studies record StudyGap::no_reference_file.
  std::filesystem::path reference_file;
};

struct SceneResults {
  Plan plan;
  std::vector<CollisionResult> solved;  // parallel to plan.jobs
  // Parallel to Scene::sections: each section's outcome, of its kind's type (scene_sections.hpp); the solves
  // of the rows with own_solves words are not counted in `total` or `collisions`.
  std::vector<std::any> sections;
  SolverStats total;           // summed over the planned collisions (not the calibrations)
  std::size_t collisions = 0;  // collisions integrated, calibrations included
};

// Runs `plan`, which plan_scene(scene) made: planning apart lets a caller refuse a scene (points outside the
// solver's range) before it prepares anything, without planning twice.
SceneResults run_scene(const Scene& scene, Plan plan, const RunSettings& settings = {});

// A scene's sections of `kind`, as their typed outcomes (in the order of Scene::sections).
template <class Outcome>
std::vector<const Outcome*> outcomes_of(const Scene& scene, const SceneResults& results,
                                        std::string_view kind) {
  std::vector<const Outcome*> outcomes;
  for (std::size_t i = 0; i < scene.sections.size(); ++i) {
    if (scene.sections[i].kind == kind)
      outcomes.push_back(&std::any_cast<const Outcome&>(results.sections[i]));
  }
  return outcomes;
}

// The result of a planned point (nullptr when the point needed no integration).
const CollisionResult* result_of(const SceneResults& results, const PlannedPoint& point);
// The end of a result (nullptr when there is no result or that end was not computed).
const EndResult* end_if_computed(const CollisionResult* result, CollisionEnd end);

}  // namespace restitution::scene
