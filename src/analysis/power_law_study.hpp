// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution fit`: ε over a grid of ζ at one end, the least-squares power law through it, the local slopes
// d ln ε / d ln ζ at each point and the large-ζ law derived in analysis/asymptotics.hpp to compare with.
#include <cstddef>
#include <functional>
#include <vector>

#include "analysis/power_law_fit.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

struct PowerLawStudy {
  std::vector<double> zeta;        // the grid, as given
  std::vector<double> eps;         // ε at each ζ, at the requested tolerance
  std::vector<LocalSlope> slopes;  // at each ζ, from solves at kMinTolerance
  PowerLawFit fit;                 // ln ε against ln ζ
  double derived_exponent = 0.0;   // ε ≈ c ζ^p as ζ → ∞ at this end (asymptotics.hpp)
  double derived_prefactor = 0.0;
};

// Throws InvalidInput for ζ beyond the checked range (require_checked_zeta of the grid's largest, which comes
// last) and as fit_power_law; `progress` (if set) hears (points done, points) after each ζ.
PowerLawStudy power_law_study(const std::vector<double>& zetas, CollisionEnd end, double tolerance,
                              const std::function<void(std::size_t, std::size_t)>& progress = {});

}  // namespace restitution
