// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[fit]] section as written: the fit (restitution/fit.hpp) of its data, the tables for the plot
// (data with error bars and each law's residuals; each law's curve with its 95 % band) and the markdown.
#include <optional>
#include <string>
#include <vector>

#include "restitution/fit.hpp"
#include "scene/scene.hpp"

namespace restitution::cli {

struct FitSection {
  FitResult result;
  std::optional<double> k;  // of the task's material
  std::string data_csv;     // v, eps, sigma, model_<law>, residual_<law>
  std::string curves_csv;   // v, eps_<law>, low_<law>, high_<law> on a log grid over the data's speeds
  std::string markdown;     // the table of the fits, the preferred law, g* (and A) with intervals
};

// Fits the task's data and formats the section. Throws InvalidInput for a material the fit cannot use.
FitSection fit_section(const scene::Scene& scene, const scene::FitTask& task);

}  // namespace restitution::cli
