// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[oblique]] section (docs/scenes.md, docs/oblique.md): each tangential model's sweep over the
// section's angles and spins, solved as `restitution oblique` solves it, in one CSV with a tangential_model
// column, and Maw, Barber & Fawcett's diagram of all of them.
#include <string>
#include <vector>

#include "cli/oblique/oblique_sweep.hpp"
#include "restitution_oblique/oblique_study.hpp"
#include "scene/scene.hpp"

namespace restitution::cli {

struct ObliqueModelRun {
  oblique::ObliqueSetup setup;
  std::vector<oblique::ObliqueImpact> impacts;
  MawModel maw;
};

struct ObliqueSection {
  std::vector<ObliqueModelRun> runs;  // one per model, in the section's order
  std::string csv;
  std::vector<std::string> plot_args;  // scripts/plots/oblique_maw.py after CSV and image; empty: no plot
  std::string markdown;                // after the plot
};

// Throws InvalidInput naming the scene, the section and the problem when an impact cannot be solved.
ObliqueSection oblique_section(const scene::Scene& scene, const scene::ObliqueTask& task);

}  // namespace restitution::cli
