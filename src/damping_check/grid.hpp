// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The damping check over a grid (a scene's [[damping_check]] section, docs/damping.md): for each recipe the
// actual ε against the requested one at the reference speed and the recipe's error there, for the
// speed-dependent recipes the speed dependence ε(v)/ε(v_ref) - 1 over requested ε × impact speed, and the
// findings table (requested 0.3, 0.5, 0.8, 0.95 at v_ref/10, v_ref and 10 v_ref). Values only; NaN where the
// end does not exist (an overdamped Tsuji member without the clamp).
#include <array>
#include <vector>

#include "damping_check/check.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::damping_check {

// One value per clamp, each a list (per speed, or one value for a speed-independent recipe).
struct ByClamp {
  std::vector<double> on, off;
};

struct RecipeGrid {
  Recipe recipe = Recipe::lammps_tsuji;
  bool speed_independent = false;
  std::vector<ByClamp> at_reference;  // per requested ε of the grid: the actual ε at the reference speed
  // Per requested ε: the recipe's own error where it is set up, (ε(v_ref) - req) / req (one value).
  std::vector<ByClamp> recipe_error_at_calibration_speed;
  // Speed-dependent recipes: per requested ε, the physical speed dependence ε(v) / ε(v_ref) - 1 per speed.
  std::vector<ByClamp> speed_dependence;
  std::vector<ByClamp> findings;  // per kFindingsEps: the actual ε at findings_speeds (one when independent)
};

inline constexpr std::array<double, 4> kFindingsEps{0.3, 0.5, 0.8, 0.95};

struct GridRequest {
  std::vector<Recipe> recipes;
  std::vector<double> eps;              // requested ε of the map and the error grids
  double reference_velocity_m_s = 1.0;  // v_ref of the speed-dependent recipes
  std::vector<double> speeds_m_s;       // speeds of the error grids
  double tolerance = SolveOptions{}.tolerance;
};

struct GridResult {
  std::array<double, 3> findings_speeds_m_s{};  // v_ref / 10, v_ref, 10 v_ref
  std::vector<RecipeGrid> recipes;              // in request order
};

// Throws InvalidInput for a value out of range, NumericalFailure when a solve fails.
GridResult check_grid(const GridRequest& request, CollisionSolver& solver);

}  // namespace restitution::damping_check
