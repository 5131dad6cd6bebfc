// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[fit]] section: measured ε(v) (a CSV file relative to the scene, or inline lists) fitted with
// the candidate laws of restitution/fit.hpp, as `restitution fit-data` does (docs/fit.md, docs/scenes.md).
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/fit.hpp"
#include "restitution/material.hpp"

namespace restitution::scene {

struct FitTask {
  std::string name;
  std::string title;
  std::string note;  // free text for the report
  // What the data points are, in the figure's legend: "measured" unless the scene says otherwise (a published
  // formula sampled at some speeds is no measurement).
  std::string data_label = "measured";
  std::string source;  // the data file as written in the scene, or "inline"
  FitData data;
  std::vector<FitCandidate> candidates;
  std::optional<std::string> material;  // a [materials.X] of the scene: A with its intervals
  // A published g* [m/s] to set beside the fitted ones (the 1999 paper's 0.32 cm/s for ice).
  std::optional<double> reference_characteristic_velocity_m_s;
  int line = 0;
};

struct Scene;

// The fit of a [[fit]] section's data with the options it ran with (the candidates, the scene's tolerance and
// method, the material's k when it names one).
struct FitOutcome {
  FitOptions options;
  FitResult result;
};

// Throws InvalidInput for data or a material the fit cannot use.
FitOutcome run_fit_section(const Scene& scene, const FitTask& task);

namespace detail {
class TomlReader;
// Reads the keys of one [[fit]] (name already read): data = "file.csv" (relative to the scene file) or
// v = [...], eps = [...] (, sigma = [...]); laws, speed_independent_end, material, title, note,
// reference_characteristic_velocity. Throws InvalidInput naming the key, or the data file's line and column.
FitTask read_fit_task(TomlReader& r, std::string name, const std::map<std::string, Material>& materials);
}  // namespace detail

}  // namespace restitution::scene
