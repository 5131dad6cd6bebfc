// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The table of scene sections that compute on their own (docs/design.md, "A new scene section touches"): one
// row per kind with its name, how one section is read and how it runs. The scene holds these sections as
// SectionTask values (scene.hpp) in the order of this table, the run step (scene_run.cpp) computes each into
// a typed outcome, and the CLI's table of writers (cli/scene/scene_section_writers.hpp, keyed by the same
// names; a test checks both tables list the same kinds) writes it. The planner's rows ([[sweep]],
// [[trajectory]], [[dashpot]]) add their collisions to the scene's shared plan first (scene_plan.hpp), and
// their run step reads them from the solved plan.
#include <any>
#include <cstddef>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/material.hpp"
#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"

namespace restitution::scene {

namespace detail {
class TomlReader;
}

// What a section's reader is given besides its table: its name (read and checked by the parser: unique, a
// file stem), the scene's materials, and the warnings a deprecated key adds to.
struct SectionContext {
  const std::string& name;
  const std::map<std::string, Material>& materials;
  std::vector<std::string>& warnings;
};

// What a section's run step is given besides its task: the scene, a solver the run step's sections share
// (one at a time), the reference solutions a work-precision study measures against (none: empty), and the
// shared plan as solved.
struct SectionRunContext {
  const Scene& scene;
  CollisionSolver& solver;
  const std::filesystem::path& reference_file;
  const std::vector<PlannedPoint>& points;     // the section's points in the plan (its row's plan hook)
  const std::vector<CollisionResult>& solved;  // parallel to Plan::jobs
  std::size_t& counted_solves;  // where a run step counts solves beside the plan's (calibrations)
};

struct SectionKind {
  const char* name;  // [[name]] in a scene file
  // Reads one section's keys into its task (InvalidInput naming the key); the parser then refuses the keys
  // nobody read.
  std::any (*parse)(detail::TomlReader& r, const SectionContext& context);
  // Computes the task into its outcome (InvalidInput or NumericalFailure naming the scene and the section).
  std::any (*run)(const SectionRunContext& context, const std::any& task);
  // Caps the task's ranges at `points` values: `run --quick`.
  void (*quick)(std::any& task, std::size_t points);
  // The report's words for what this kind integrates outside the shared plan ("" for nothing; rows with the
  // same words are named once).
  const char* own_solves;
  // The planner's rows: adds the task's collisions to the shared plan before anything is solved and returns
  // its points, which the run step reads (InvalidInput for a point outside the solver's range, before the
  // output folder exists). Null for a row that solves its own.
  std::vector<PlannedPoint> (*plan)(const Scene& scene, const std::any& task, JobTable& jobs) = nullptr;
};

// Every row, in the order the parser reads the kinds.
const std::vector<SectionKind>& section_kinds();
// The row of `name`; nullptr when no row has it.
const SectionKind* find_section_kind(std::string_view name);

// Whether the scene has a section of `kind`.
bool has_sections(const Scene& scene, std::string_view kind);

// A scene's sections of `kind`, as their typed tasks (the any_cast the rows' functions do).
template <class Task>
std::vector<const Task*> tasks_of(const Scene& scene, std::string_view kind) {
  std::vector<const Task*> tasks;
  for (const SectionTask& s : scene.sections) {
    if (s.kind == kind) tasks.push_back(&std::any_cast<const Task&>(s.task));
  }
  return tasks;
}

}  // namespace restitution::scene
