// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[adhesion]] section written (docs/scenes.md, docs/adhesion.md): what scene/scene_adhesion_run
// computes, as the CSV of `sweep --adhesion`, the arguments of the ε(v) figure and the report's words.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_adhesion_run.hpp"

namespace restitution::cli {

struct AdhesionSection {
  scene::AdhesionOutcome outcome;
  std::string csv;
  std::vector<std::string> plot_args;  // scripts/plots/scene_adhesion.py after CSV and image
  std::string markdown;                // after the plot
};

// Throws InvalidInput naming the scene, the section and the problem.
AdhesionSection adhesion_section(const scene::Scene& scene, const scene::AdhesionTask& task);

}  // namespace restitution::cli
