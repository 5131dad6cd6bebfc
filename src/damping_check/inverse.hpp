// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The damping check inverted (docs/damping.md): the ε to request from a DEM code's recipe so that it gives a
// target ε at one impact speed, and the ε(v) that request then gives at other speeds.
#include <vector>

#include "damping_check/check.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::damping_check {

// The inverse: which ε to request from `recipe` so that it gives `target_eps` at `target_velocity_m_s` with
// `clamp`. Speed-dependent recipes are set up at the target speed (it becomes their reference speed: YADE's
// vn); `speeds_m_s` are where the answer's ε(v) is then reported.
struct InverseRequest {
  Recipe recipe = Recipe::lammps_tsuji;
  double target_eps = 0.5;
  double target_velocity_m_s = 1.0;
  Clamp clamp = Clamp::on;
  std::vector<double> speeds_m_s{1.0};
  double tolerance = SolveOptions{}.tolerance;
};

struct InverseResult {
  double eps_to_request = 0.0;  // the recipe's input (the code's restitution parameter)
  CheckResult check;            // that request checked at the target speed's clamp and `speeds_m_s`
};

// Throws InvalidInput when the target is out of (0, 1) or outside what the recipe can give with that clamp
// (the message names the reachable range), NumericalFailure when a solve fails.
InverseResult invert_recipe(const InverseRequest& request, CollisionSolver& solver);

// The inverse for each clamp of `clamps` in turn (its own `clamp` is not read): one result per clamp, in that
// order (`damping-check --target-eps`).
std::vector<InverseResult> invert_recipe_for(InverseRequest request, const std::vector<Clamp>& clamps,
                                             CollisionSolver& solver);

}  // namespace restitution::damping_check
