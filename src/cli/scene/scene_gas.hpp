// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[gas]] section (docs/scenes.md, docs/gas.md): the cooling curve of the material's spheres with
// the law's ε(v), computed as `restitution gas` computes it, beside Haff's law of a constant ε.
#include <optional>
#include <string>
#include <vector>

#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"
#include "scene/scene.hpp"

namespace restitution::cli {

struct GasSection {
  gas::CoolingRequest request;
  gas::CoolingCurve curve;
  std::optional<gas::Thermostat> thermostat;  // the driven gas's, with its steady state
  std::optional<gas::SteadyState> steady;
  std::string csv;
  std::vector<std::string> plot_args;  // scripts/plots/gas_cooling.py after CSV and PNG
  std::string markdown;                // after the plot
};

// Throws InvalidInput naming the section's key when the gas cannot be computed.
GasSection gas_section(const scene::Scene& scene, const scene::GasTask& task);

}  // namespace restitution::cli
