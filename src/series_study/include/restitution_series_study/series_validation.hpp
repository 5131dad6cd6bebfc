// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Validation of every series and approximation against the numerical solver (CollisionSolver) and
// convergence radii of the recomputed series. Library code: computes, never writes.
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/series.hpp"

namespace restitution::series {

struct ValidationOptions {
  double zeta_min = 1e-4;
  double zeta_max = 10.0;
  int points_per_decade = 20;  // log grid, both ends included
  double tolerance = 1e-11;    // solver accuracy contract, relative to min(ε, 1-ε)
  int naive_order = 40;        // terms of the recomputed naive series (c_1 ... c_N)
  int delayed_order = 60;      // terms of the recomputed delayed-recovery series (h_0 ... h_N)
};

// One approximation as validated: its name, the end it describes, and how it was built.
struct Candidate {
  std::string name;         // an approximation name (series_named.hpp), a series with its coefficients:
                            // "naive-series:published", "naive-series:computed-40", "pade-1999", ...
  CollisionEnd end;         // the end the solver is compared with
  std::string description;  // coefficients and source
};

struct PointError {
  Value value;                          // the approximation at ζ
  double relative_error_eps = 0;        // |ε_a - ε| / ε
  double relative_error_one_minus = 0;  // |(1-ε)_a - (1-ε)| / (1-ε)
};

struct ValidationRow {
  double zeta = 0;
  PerEnd<Value> solver;            // the solver's ε and 1-ε at each end
  std::vector<PointError> errors;  // one per candidate, same order as ValidationReport::candidates
};

// First grid ζ at which the relative error exceeds the threshold (NaN: never on the grid).
struct Crossing {
  double threshold = 0;
  double zeta_eps = 0;
  double zeta_one_minus_eps = 0;
};

// Large-ζ behaviour: local exponent d ln ε / d ln ζ between ζ = 1e3 and 1.1e3 of the approximation
// (NaN where ε <= 0) and of the solver at the same end, and the exponent the closed form implies.
struct LargeZeta {
  double approximation_slope = 0;
  double solver_slope = 0;
  double implied_exponent = 0;  // NaN for truncated series (they grow like their last term)
};

struct CandidateSummary {
  std::vector<Crossing> crossings;  // thresholds 1e-3, 1e-6, 1e-10
  LargeZeta large_zeta;
};

// Radius of convergence in ζ from the coefficients of Σ coef_k x^k with x = ζ (or x = sqrt(ζ), then
// the radius in ζ is the square of the one in x).
struct RadiusEstimate {
  std::string series;  // "a", "b", "c" (in ζ), "h" (in sqrt ζ), "v" (in λ = w^{5/2}, radius in λ)
  int terms = 0;
  // ratio, domb_sykes and domb_sykes_slope are NaN when the signs of the last half are neither constant
  // nor alternating (complex singularities).
  double ratio = 0;             // |coef_{N-1}/coef_N| (in ζ)
  double root = 0;              // min over the last third of |coef_k|^{-1/k} (in ζ)
  double domb_sykes = 0;        // 1/|intercept| of coef_k/coef_{k-1} against 1/k over the last half (in ζ)
  double domb_sykes_slope = 0;  // slope of that fit: -(1+g)/R for a singularity (1 ∓ ζ/R)^g
};

struct ValidationReport {
  ValidationOptions options;
  std::vector<Candidate> candidates;
  std::vector<ValidationRow> rows;
  std::vector<CandidateSummary> summaries;  // one per candidate
  std::vector<RadiusEstimate> radii;
};

// Throws InvalidInput for a bad grid or order, NumericalFailure when the solver fails.
ValidationReport validate(const ValidationOptions& options);

// Radius estimate from coefficients coef_0 ... coef_N of a series in x; `in_sqrt_zeta` squares the result.
RadiusEstimate estimate_radius(const std::string& name, const std::vector<double>& coef, bool in_sqrt_zeta);

}  // namespace restitution::series
