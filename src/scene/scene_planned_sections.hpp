// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The sections whose collisions the scene's planner shares, as their rows of scene_sections.cpp use them:
// [[sweep]], [[trajectory]] and [[dashpot]] add their points to the shared plan (scene_plan.hpp) and read
// them back solved; [[calibration]] finds its root with the run step's solver and counts its solves with the
// plan's. Each reader fails through the reader naming the key (InvalidInput); the name is read by the parser.
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_plan.hpp"
#include "scene/scene_results.hpp"
#include "scene/scene_sections.hpp"
#include "scene/section_keys.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene {

namespace detail {
// The keys every plotted section has besides its name (read by the parser): title and ends; and where it
// starts.
template <typename Task>
void read_heading(TomlReader& r, const SectionContext& context, Task& task) {
  task.line = r.line();
  task.name = context.name;
  task.title = r.text("title").value_or(task.name);
  task.ends = read_ends(r);
}

Sweep read_sweep(TomlReader& r, const SectionContext& context);
Trajectory read_trajectory(TomlReader& r, const SectionContext& context);
CalibrationTask read_calibration(TomlReader& r, const SectionContext& context);
DashpotCheck read_dashpot(TomlReader& r, const SectionContext& context);
}  // namespace detail

std::vector<PlannedPoint> plan_sweep(const Scene& scene, const Sweep& sweep, JobTable& jobs);
std::vector<PlannedPoint> plan_trajectory(const Scene& scene, const Trajectory& trajectory, JobTable& jobs);
std::vector<PlannedPoint> plan_dashpot(const Scene& scene, const DashpotCheck& dashpot, JobTable& jobs);

// The studies of a sweep (approximations, fits, the empirical law) over its solved points.
SweepOutcome run_sweep_section(const SectionRunContext& context, const Sweep& sweep);
TrajectoryOutcome run_trajectory_section(const SectionRunContext& context, const Trajectory& trajectory);
// The dash-pot's solved points against the closed forms.
DashpotOutcome run_dashpot_section(const SectionRunContext& context, const DashpotCheck& dashpot);
// Throws InvalidInput naming the file, the line and the key when ε is out of the calibration's range.
CalibrationOutcome run_calibration_section(const SectionRunContext& context, const CalibrationTask& task);

}  // namespace restitution::scene
