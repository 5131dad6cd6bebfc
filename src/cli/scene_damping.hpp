#pragma once
// A scene's [[damping_check]] section: for each DEM damping recipe the ε it really gives against the
// requested one (clamp on and off, at the reference speed) and, for the speed-dependent recipes, the relative
// error over requested ε × impact speed (docs/damping.md).
#include <string>
#include <vector>

#include "scene/scene.hpp"

namespace restitution::cli {

struct DampingPlot {
  std::string name;  // the CSV and PNG are <name>.csv, <name>.png
  std::string csv;
  std::string script;             // scripts/plots/<script>.py
  std::vector<std::string> args;  // after CSV and PNG
  std::string caption;            // markdown after the plot
};

struct DampingSection {
  std::vector<DampingPlot> plots;  // the requested-vs-actual map first, then one error map per recipe
  std::string findings;            // markdown: requested 0.3 / 0.5 / 0.8 / 0.95 -> actual per recipe, clamp
};

// Throws InvalidInput for a recipe or value out of range, NumericalFailure when a solve fails.
DampingSection damping_section(const scene::Scene& scene, const scene::DampingCheckTask& task);

}  // namespace restitution::cli
