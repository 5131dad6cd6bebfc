#pragma once
// The tables of a scene's results (CSV text) and the columns they hold, shared by the files, the plots and
// the report of `restitution run`.
#include <string>
#include <vector>

#include "restitution/scene.hpp"
#include "restitution/scene_run.hpp"

namespace restitution::cli {

// A table as named columns of numbers (NaN where a value does not exist).
struct Table {
  std::vector<std::string> columns;
  std::vector<std::vector<double>> rows;
  [[nodiscard]] std::string csv() const;
  [[nodiscard]] std::size_t column(const std::string& name) const;  // index; throws if absent
};

// Suffix of an end in column names: "naive" | "delayed_recovery".
const char* end_column(CollisionEnd end);

Table sweep_table(const scene::Scene& scene, const scene::SceneResults& results, std::size_t sweep);
Table trajectory_table(const scene::SceneResults& results, std::size_t trajectory);
Table dashpot_table(const scene::Scene& scene, const scene::SceneResults& results, std::size_t dashpot);

}  // namespace restitution::cli
