// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A scene's [[damping_check]] section (docs/damping.md): the ε each DEM damping recipe really gives against
// the requested one, clamp on and off, and the relative error over requested ε × impact speed for the
// speed-dependent ones (damping_check/grid.hpp computes it). The CLI writes it (cli/scene/scene_damping.cpp).
#include <string>
#include <vector>

#include "damping_check/damping_check_parameters.hpp"
#include "damping_check/grid.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::scene {

struct DampingCheckTask {
  std::string name;
  std::string title;
  // The check's inputs as the keys give them (the rows of damping_check/damping_check_parameters.hpp that
  // are keys: velocity); the grids below are the section's own lists.
  damping_check::DampingCheckInputs inputs;
  std::vector<std::string> recipes;  // recipe names (damping_check/recipes.hpp); default: every recipe
  std::vector<double> eps;           // requested ε in (0, 1); default 0.05, 0.10, ..., 0.95, 0.99
  std::vector<double> speeds;        // impact speeds of the error maps [m/s]; default 0.1 to 10, 9 points
  int line = 0;
};

damping_check::GridResult run_damping_check(const DampingCheckTask& task, double tolerance,
                                            CollisionSolver& solver);

namespace detail {
class TomlReader;
// Reads the keys of one [[damping_check]] (name already read). Throws InvalidInput naming the key.
DampingCheckTask read_damping_check_task(TomlReader& r, std::string name);
}  // namespace detail

}  // namespace restitution::scene
