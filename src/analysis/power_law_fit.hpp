// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Large-ζ power laws ε ≈ c ζ^p: least-squares fits of ln ε against ln ζ, and local slopes d ln ε / d ln ζ
// from Richardson-extrapolated central differences of tightly converged solves, with error estimates.
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"

namespace restitution {

struct PowerLawFit {
  double exponent = 0.0;         // p in ε ≈ c ζ^p
  double exponent_stderr = 0.0;  // ordinary least-squares standard error of p
  double prefactor = 0.0;        // c
  double log_prefactor_stderr = 0.0;
  double max_residual = 0.0;  // largest |ln ε - ln c - p ln ζ| over the points
  int points = 0;
};

// Fits ln eps = ln c + p ln zeta (Eigen least squares). Throws InvalidInput for fewer than 3 points,
// mismatched sizes or non-positive values.
PowerLawFit fit_power_law(const std::vector<double>& zeta, const std::vector<double>& eps);

struct LocalSlope {
  double zeta = 0.0;
  double slope = 0.0;           // d ln ε / d ln ζ
  double error_estimate = 0.0;  // truncation (Richardson difference) plus the solver-noise bound
};

// Central differences in ln ζ with steps h and h/2 (h = 0.05), Richardson-extrapolated; each solve at the
// given tolerance, whose error bound T/3 enters the noise part of the estimate as T/h.
LocalSlope local_slope(CollisionSolver& solver, double zeta, CollisionEnd end, double tolerance);

// Log-spaced grid of `points` values from zeta_min to zeta_max (both included). Throws InvalidInput
// unless 0 < zeta_min < zeta_max and points >= 2.
std::vector<double> log_grid(double zeta_min, double zeta_max, int points);

}  // namespace restitution
