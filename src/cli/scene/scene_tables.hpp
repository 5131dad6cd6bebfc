// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The tables of a scene's results (CSV text) and the columns they hold, shared by the files, the plots and
// the report of `restitution run`.
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/scene_results.hpp"

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

Table sweep_table(const scene::Sweep& sweep, const scene::SweepOutcome& outcome);
Table trajectory_table(const scene::TrajectoryOutcome& outcome);
Table dashpot_table(const scene::DashpotCheck& dashpot, const scene::DashpotOutcome& outcome);

// A number of the report: 10 significant digits, "—" where there is none (NaN).
std::string report_number(double v);
// The items with `separator` between them.
std::string join(const std::vector<std::string>& items, const char* separator = ",");

}  // namespace restitution::cli
