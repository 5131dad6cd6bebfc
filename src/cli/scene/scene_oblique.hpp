// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[oblique]] section written (docs/scenes.md, docs/oblique.md): the sweeps scene/scene_oblique_run
// computed, in one CSV with a tangential_model column, Maw, Barber & Fawcett's diagram of all of them, a
// sentence per model and summary.json's object.
#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_oblique_run.hpp"

namespace restitution::cli {

// Writes the section: NAME.csv (a tangential_model column, then the columns of `oblique --out`), Maw's
// diagram where it is drawn, a sentence per model, a warning per model with failed impacts, and
// summary.json's oblique_NAME (χ, ε, each model's sticking limit).
void write_oblique_section(const scene::Scene& scene, const scene::ObliqueTask& task,
                           const scene::ObliqueOutcome& outcome, SectionOutput& out);

}  // namespace restitution::cli
