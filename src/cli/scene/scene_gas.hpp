// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[gas]] section written (docs/scenes.md, docs/gas.md): the CSV, the plot's arguments and the
// report's words of what src/scene computed (scene/scene_gas.hpp).
#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_gas.hpp"

namespace restitution::cli {

// The CSV, the plot, the words and summary.json's "gas_<name>" object: Haff's tau0 and the curve's end.
void write_gas_section(const scene::Scene& scene, const scene::GasTask& task,
                       const scene::GasOutcome& outcome, SectionOutput& out);

}  // namespace restitution::cli
