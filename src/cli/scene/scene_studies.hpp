// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[work_precision]] and [[stability]] sections written together under "Other studies": each
// study's summary lines (scene_text.hpp) in the report and in summary.json's "studies", and a work-precision
// study's points, summary and plot.
#include <vector>

#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"

namespace restitution::cli {

void write_studies(const scene::Scene& scene, const std::vector<SectionResult>& studies, SectionOutput& out);

}  // namespace restitution::cli
