// SPDX-License-Identifier: BSD-3-Clause
#include "analysis/power_law_fit.hpp"

#include <fmt/core.h>

#include <Eigen/Dense>
#include <cmath>

#include "restitution/errors.hpp"

namespace restitution {

PowerLawFit fit_power_law(const std::vector<double>& zeta, const std::vector<double>& eps) {
  const auto n = static_cast<Eigen::Index>(zeta.size());
  if (zeta.size() != eps.size()) throw InvalidInput("power-law fit: zeta and eps differ in length");
  if (n < 3) throw InvalidInput(fmt::format("power-law fit needs at least 3 points, got {}", n));
  Eigen::MatrixXd design(n, 2);
  Eigen::VectorXd target(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    if (!(zeta[k] > 0.0) || !(eps[k] > 0.0))
      throw InvalidInput(
          fmt::format("power-law fit needs zeta > 0 and eps > 0, got zeta={} eps={}", zeta[k], eps[k]));
    design(i, 0) = 1.0;
    design(i, 1) = std::log(zeta[k]);
    target(i) = std::log(eps[k]);
  }
  const Eigen::Vector2d coefficients = design.colPivHouseholderQr().solve(target);
  const Eigen::VectorXd residuals = target - design * coefficients;
  const double variance = residuals.squaredNorm() / static_cast<double>(n - 2);
  const Eigen::Matrix2d covariance = variance * (design.transpose() * design).inverse();
  PowerLawFit fit;
  fit.exponent = coefficients(1);
  fit.exponent_stderr = std::sqrt(covariance(1, 1));
  fit.prefactor = std::exp(coefficients(0));
  fit.log_prefactor_stderr = std::sqrt(covariance(0, 0));
  fit.max_residual = residuals.cwiseAbs().maxCoeff();
  fit.points = static_cast<int>(n);
  return fit;
}

LocalSlope local_slope(CollisionSolver& solver, double zeta, CollisionEnd end, double tolerance) {
  if (!(zeta > 0.0)) throw InvalidInput(fmt::format("local slope needs zeta > 0, got {}", zeta));
  constexpr double kStep = 0.05;  // in ln ζ
  SolveOptions options;
  options.tolerance = tolerance;
  options.ends = EndSet{end};
  const auto log_eps = [&](double log_zeta) {
    const CollisionResult r = solver.solve(ContactLaw::hertz_natural(std::exp(log_zeta)), options);
    return std::log(end_of(r, end).eps);
  };
  const double s = std::log(zeta);
  const auto central = [&](double h) { return (log_eps(s + h) - log_eps(s - h)) / (2.0 * h); };
  const double coarse = central(kStep);
  const double fine = central(0.5 * kStep);
  LocalSlope result;
  result.zeta = zeta;
  result.slope = (4.0 * fine - coarse) / 3.0;
  // |fine - coarse|/3 estimates the error of `fine`, a bound for the extrapolated value; each ln ε carries
  // at most tolerance/3 (relative error of ε, the accuracy contract), which the combination amplifies to
  // tolerance/h.
  result.error_estimate = std::abs(fine - coarse) / 3.0 + tolerance / kStep;
  return result;
}

std::vector<double> log_grid(double zeta_min, double zeta_max, int points) {
  if (!(zeta_min > 0.0) || !(zeta_max > zeta_min) || !std::isfinite(zeta_max))
    throw InvalidInput(fmt::format("need 0 < zeta-min < zeta-max, got {} and {}", zeta_min, zeta_max));
  if (points < 2) throw InvalidInput(fmt::format("--points must be at least 2, got {}", points));
  std::vector<double> grid(static_cast<std::size_t>(points));
  const double a = std::log(zeta_min);
  const double b = std::log(zeta_max);
  for (int i = 0; i < points; ++i)
    grid[static_cast<std::size_t>(i)] = std::exp(a + (b - a) * i / (points - 1));
  grid.front() = zeta_min;
  grid.back() = zeta_max;
  return grid;
}

}  // namespace restitution
