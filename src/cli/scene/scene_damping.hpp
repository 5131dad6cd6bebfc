// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[damping_check]] section as written (damping_check/grid.hpp computes it): for each DEM damping
// recipe the ε it really gives against the requested one (clamp on and off, at the reference speed) and, for
// the speed-dependent recipes, the relative error over requested ε × impact speed (docs/damping.md).
#include <string>
#include <vector>

#include "cli/scene/scene_section_writers.hpp"
#include "damping_check/grid.hpp"
#include "scene/scene.hpp"
#include "scene/scene_damping_check.hpp"

namespace restitution::cli {

struct DampingPlot {
  std::string name;  // the CSV and PNG are <name>.csv, <name>.png
  std::string csv;
  std::string script;             // scripts/plots/<script>.py
  std::vector<std::string> args;  // after CSV and PNG
  std::string caption;            // markdown after the plot
};

struct DampingSection {
  std::vector<DampingPlot> plots;  // the requested-vs-actual map first, then one error map per recipe
  std::string findings;            // markdown: requested 0.3 / 0.5 / 0.8 / 0.95 -> actual per recipe, clamp
};

// The section's files, plots and findings from the grid the scene computed for `task` (formatting only).
DampingSection damping_section(const scene::DampingCheckTask& task, const damping_check::GridResult& grid);

// Writes the section: each plot's CSV, figure and caption, then the findings.
void write_damping_check_section(const scene::Scene& scene, const scene::DampingCheckTask& task,
                                 const damping_check::GridResult& grid, SectionOutput& out);

}  // namespace restitution::cli
