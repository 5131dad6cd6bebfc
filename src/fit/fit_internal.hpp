// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parts of fit_data (restitution/fit.hpp): the weights and quantiles every law shares, the fit of
// viscoelastic Hertz (β on the fast table), of the speed-independent members (one ε, inverted with the
// solver) and the residual tests.
#include <cstddef>
#include <limits>
#include <vector>

#include "restitution/fit.hpp"

namespace restitution::fit_detail {

// What every candidate's fit needs from the data.
struct Problem {
  const FitData* data = nullptr;
  std::vector<double> weight;  // 1/σ², or 1 when σ is estimated
  bool sigma_estimated = false;
  // Δχ² of the 68 % and 95 % intervals before scaling: z² (known σ) or t²_{n-1} (estimated σ, multiplied by
  // χ²_min/(n-1) per law).
  double delta68 = 1.0;
  double delta95 = 3.84;
  [[nodiscard]] std::size_t size() const { return weight.size(); }
};

Problem make_problem(const FitData& data, double level68, double level95);

// Σ w (ε_i - model_i)².
double chi_square(const Problem& problem, const std::vector<double>& model_eps);

// Fills value, status, intervals, chi2 and model_eps of `fit` (the rest is filled by fit_data).
void fit_hertz(const Problem& problem, LawFit& fit);
void fit_speed_independent(const Problem& problem, const FitOptions& options, CollisionSolver& solver,
                           LawFit& fit);

ResidualTests residual_tests(const Problem& problem, const std::vector<double>& model_eps);

// A bound that lies beyond the checked range: not a number.
inline void set_edge_high(FitInterval& interval) {
  interval.high_at_edge = true;
  interval.high = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace restitution::fit_detail
