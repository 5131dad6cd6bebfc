// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The ε a deck's lines give, solved with the collision solver: at the deck's own pair and at pairs of other
// sizes of the same material (where codes whose parameters contain m_eff or R_eff stop being exact).
#include <vector>

#include "dem/deck.hpp"
#include "restitution/collision_solver.hpp"

namespace restitution::dem {

// ε of the law with β [s^{1/5} m^{-1/5}] at impact speed v [m/s], at `end` (β = 0: ε = 1).
double eps_for(double beta, double velocity_m_s, CollisionEnd end, double tolerance, CollisionSolver& solver);

struct SizeCheck {
  double radius_factor = 1.0;  // radii scaled by this, masses by its cube (same density)
  double eps_lines = 0.0;      // what the deck's parameters give that pair
  double eps_law = 0.0;        // what the material's law gives it
};

// One SizeCheck per factor, at impact speed v [m/s]; A [s] is the law's dissipative constant.
std::vector<SizeCheck> size_checks(const Deck& deck, const Pair& pair, double dissipative_constant_s,
                                   double velocity_m_s, const std::vector<double>& factors, double tolerance,
                                   CollisionSolver& solver);

}  // namespace restitution::dem
