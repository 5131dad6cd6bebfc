// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The tables of a scene's results (CSV text) and the columns they hold, shared by the files, the plots and
// the report of `restitution run`.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_run.hpp"

// Sweep tables hold, per approximation, <label>_eps and <label>_rel_diff = <label>_eps / eps - 1 against the
// numerics at the end the approximation describes (ApproximationColumn::relative_difference); dash-pot tables
// the closed-form checks of DashpotOutcome. The tables only arrange the studies' numbers.

namespace restitution::cli {

// A table as named columns of numbers (NaN where a value does not exist).
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] std::string csv() const;
  [[nodiscard]] std::size_t column(const std::string& name) const;  // index; throws if absent
};

// index: of the task in the scene (Scene::sweeps, ::trajectories, ::dashpots).
Table sweep_table(const scene::Scene& scene, const scene::SceneResults& results, std::size_t index);
Table trajectory_table(const scene::SceneResults& results, std::size_t index);
Table dashpot_table(const scene::Scene& scene, const scene::SceneResults& results, std::size_t index);

}  // namespace restitution::cli
