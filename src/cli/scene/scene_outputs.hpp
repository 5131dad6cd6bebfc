// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Everything `restitution run` writes into a scene's output folder: CSV tables, summary.json, PNG plots and
// report.md. Files are written atomically; a missing matplotlib costs the plots only.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

namespace restitution::cli {

struct WrittenOutputs {
  std::vector<std::string> files;     // names inside the folder
  std::vector<std::string> warnings;  // one line each (plots that could not be made)
};

WrittenOutputs write_scene_outputs(const scene::Scene& scene, const scene::SceneResults& results,
                                   const std::filesystem::path& folder, double seconds);

}  // namespace restitution::cli
