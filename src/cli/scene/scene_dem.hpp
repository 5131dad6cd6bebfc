// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[dem]] section written (scene/scene_dem.hpp computes it): the CSV of restitution's ε(v) and the
// code's, the plot, the lines and the table in the report, the code's run in summary.json.
#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_dem.hpp"

namespace restitution::cli {

void write_dem_section(const scene::Scene& scene, const scene::DemTask& task,
                       const scene::DemOutcome& outcome, SectionOutput& out);

}  // namespace restitution::cli
