// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[fit]] section written (scene/scene_fit.hpp fits it): the tables for the plot (data with error
// bars and each law's residuals; each law's curve with its 95 % band), the plot, the markdown (the table of
// the fits, the preferred law, g* and A with intervals) and the fit-data JSON object under "fit_<name>".
#include "cli/scene/scene_section_writers.hpp"
#include "scene/scene.hpp"
#include "scene/scene_fit.hpp"

namespace restitution::cli {

void write_fit_section(const scene::Scene& scene, const scene::FitTask& task, const scene::FitOutcome& fit,
                       SectionOutput& out);

}  // namespace restitution::cli
