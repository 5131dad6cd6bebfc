// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The numerics of a scene set against what they are compared with: approximation columns, an empirical law
// and the dash-pot's closed forms. Every difference, maximum and range the report quotes is computed here.
#include <vector>

#include "restitution/collision_solver.hpp"
#include "scene/scene.hpp"
#include "scene/scene_results.hpp"

namespace restitution::scene::detail {

// results: parallel to the task's points, nullptr where a point was not integrated.
using PointResults = std::vector<const CollisionResult*>;

// Fills relative_difference and comparison of every approximation column against the ε the solver found at
// the column's end (zeta: the sweep's points).
void compare_approximations(const std::vector<double>& zeta, const PointResults& results,
                            SweepExtras& extras);

// The empirical law ε = coefficient (v / unit)^exponent at each impact speed [m/s], and its largest deviation
// from the computed ε at the naive end (the delayed-recovery end when the sweep has no naive end).
void add_empirical(const EmpiricalLaw& law, EndSet ends, const std::vector<double>& velocity_m_s,
                   const PointResults& results, SweepExtras& extras);

// The dash-pot's ε at each damping ratio and requested end against its closed form.
DashpotOutcome check_dashpot(const DashpotCheck& check, const std::vector<double>& damping_ratio,
                             const PointResults& results);

}  // namespace restitution::scene::detail
