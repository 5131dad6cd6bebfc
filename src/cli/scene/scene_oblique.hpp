// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[oblique]] section written (docs/scenes.md, docs/oblique.md): the sweeps scene/scene_oblique_run
// computes, in one CSV with a tangential_model column, Maw, Barber & Fawcett's diagram of all of them, and a
// sentence per model.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_oblique_run.hpp"

namespace restitution::cli {

struct ObliqueSection {
  scene::ObliqueOutcome outcome;
  std::string csv;
  std::vector<std::string> plot_args;  // scripts/plots/oblique_maw.py after CSV and image; empty: no plot
  std::string markdown;                // after the plot
};

// Throws InvalidInput naming the scene, the section and the problem when an impact cannot be solved.
ObliqueSection oblique_section(const scene::Scene& scene, const scene::ObliqueTask& task);

}  // namespace restitution::cli
