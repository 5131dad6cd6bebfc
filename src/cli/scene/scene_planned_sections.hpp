// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The writers of the planner's sections (rows of scene_section_writers.cpp): a [[sweep]]'s table, figure,
// report paragraph and summary.json object; a [[trajectory]]'s and a [[dashpot]]'s; and the calibrations, all
// in one table after the sections written in the file's order.
#include <any>
#include <vector>

#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_results.hpp"

namespace restitution::cli {

void write_sweep_section(const scene::Scene& scene, const scene::Sweep& sweep,
                         const scene::SweepOutcome& outcome, SectionOutput& out);
void write_trajectory_section(const scene::Scene& scene, const scene::Trajectory& trajectory,
                              const scene::TrajectoryOutcome& outcome, SectionOutput& out);
void write_dashpot_section(const scene::Scene& scene, const scene::DashpotCheck& dashpot,
                           const scene::DashpotOutcome& outcome, SectionOutput& out);
// Every [[calibration]] of the scene (`sections`, in file order) in one table; nothing when there is none.
void write_calibrations(const scene::Scene& scene, const std::vector<SectionResult>& sections,
                        SectionOutput& out);

}  // namespace restitution::cli
