// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The damping check's parameters declared once: one row per field of DampingCheckInputs with its name,
// member, unit, check and help (restitution/parameter_table.hpp). The options of `restitution damping-check`
// are made from this table, and the keys of a scene's [[damping_check]] that mean the same: velocity. A scene
// checks grids where the command checks one point, so its lists (recipes, eps, speeds) are the section's own
// keys, checked with the rows' checks (a recipe's name, eps's range). What only the command has (--json, the
// speed range --velocity-range) stays the command's. A new parameter is a member of DampingCheckInputs, a row
// here and its use in the command's request (and the section's, when a scene takes it).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/parameter_table.hpp"
#include "restitution/solve_types.hpp"

namespace restitution::damping_check {

struct DampingCheckInputs {
  std::string recipe;                    // one recipe's name (recipe_names()); a scene: the list `recipes`
  std::optional<double> eps;             // one requested ε; a scene: the list `eps` of its map
  std::optional<double> target_eps;      // the inverse: the ε wanted at velocity_m_s
  bool map = false;                      // the requested ε 0.05, 0.10, ..., 0.95, 0.99 (map_eps_grid)
  std::string clamp = "both";            // on, off or both (clamps_from_name); a scene checks both
  double velocity_m_s = 1.0;             // reference speed of the speed-dependent recipes [m/s]
  double tolerance = kDefaultTolerance;  // a scene's is the scene's own
};

using DampingCheckField = ParameterField<DampingCheckInputs>;

// The fields in the order the command's help lists them.
const std::vector<DampingCheckField>& damping_check_fields();
// The field of this name; throws std::out_of_range for a name the table lacks.
const DampingCheckField& damping_check_field(std::string_view name);

}  // namespace restitution::damping_check
