// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[dem]] section: the DEM code's input lines for a scene material, restitution's ε(v) for them
// and, for LAMMPS and LIGGGHTS, the ε(v) the code itself measures (dem/code_runner.hpp, dem/lines_check.hpp).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace restitution::cli {

struct DemSection {
  std::string markdown;  // the report text after the plot
  std::string csv;       // velocity_m_s, eps_restitution[, eps_<code>, rel_diff, <code>_run (ok | failed)]
  std::vector<std::string> plot_args;  // for scripts/plots/scene_xy.py after CSV and PNG
  std::vector<std::string> warnings;   // e.g. the code is not installed, or its run failed
  std::string code_run;                // "ok", "failed", "not installed" or "not asked" (summary.json)
  std::string code_failure;            // what went wrong when it failed (dem::DemMeasurement::failure)
};

// Throws InvalidInput for a task the code cannot express (an end it cannot reach).
DemSection dem_section(const scene::Scene& scene, const scene::DemTask& task);

}  // namespace restitution::cli
