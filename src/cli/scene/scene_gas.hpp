// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[gas]] section written (docs/scenes.md, docs/gas.md): the CSV, the plot's arguments and the
// report's words of what src/scene computed (scene/scene_gas.hpp).
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_gas.hpp"

namespace restitution::cli {

struct GasSection {
  scene::GasOutcome outcome;
  std::string csv;
  std::vector<std::string> plot_args;  // scripts/plots/gas_cooling.py after CSV and PNG
  std::string markdown;                // after the plot
};

// Throws InvalidInput naming the section's key when the gas cannot be computed.
GasSection gas_section(const scene::Scene& scene, const scene::GasTask& task);

}  // namespace restitution::cli
