// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[adhesion]] section written (docs/scenes.md, docs/adhesion.md): what scene/scene_adhesion_run
// computed, as the CSV of `sweep --adhesion`, the ε(v) figure, the report's words and summary.json.
#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_adhesion.hpp"
#include "scene/scene_adhesion_run.hpp"

namespace restitution::cli {

// Writes the section: NAME.csv (the columns of `sweep --adhesion`), the figure of ε(v) with the sticking
// region shaded (scripts/plots/scene_adhesion.py), the report's paragraph and summary.json's adhesion_NAME
// (the sticking speed, the damping, the closed forms).
void write_adhesion_section(const scene::Scene& scene, const scene::AdhesionTask& task,
                            const scene::AdhesionOutcome& outcome, SectionOutput& out);

}  // namespace restitution::cli
