// SPDX-License-Identifier: BSD-3-Clause
#include "fit/fit_curves.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include "restitution/collision_solver.hpp"

namespace restitution {

FitCurves fit_curves(const FitData& data, const FitResult& result, const FitOptions& options) {
  const auto [lo, hi] = std::minmax_element(data.velocity_m_s.begin(), data.velocity_m_s.end());
  FitCurves out;
  out.velocity_m_s.resize(kFitCurvePoints);
  for (int k = 0; k < kFitCurvePoints; ++k) {
    out.velocity_m_s[k] = *lo * std::pow(*hi / *lo, static_cast<double>(k) / (kFitCurvePoints - 1));
  }
  CollisionSolver solver;
  SolveOptions solve;
  solve.tolerance = options.tolerance;
  solve.method = options.method;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t j = 0; j < result.fits.size(); ++j) {
    const LawFit& f = result.fits[j];
    if (f.status != FitStatus::converged) continue;
    FitCurve curve;
    curve.fit = j;
    const std::array<double, 3> parameters{f.value, f.ci95.high_at_edge ? nan : f.ci95.high, f.ci95.low};
    const std::array<std::vector<double>*, 3> columns{&curve.eps, &curve.band_low, &curve.band_high};
    for (int c = 0; c < 3; ++c) {
      auto eps_at = [&](double v) {
        return std::isnan(parameters[c]) ? nan : fit_model_eps(f.candidate, parameters[c], v, solver, solve);
      };
      // A speed-independent law needs one solve per parameter.
      const double constant = speed_independent(f.candidate.law) ? eps_at(1.0) : nan;
      for (const double v : out.velocity_m_s) {
        columns[c]->push_back(speed_independent(f.candidate.law) ? constant : eps_at(v));
      }
    }
    out.curves.push_back(std::move(curve));
  }
  return out;
}

}  // namespace restitution
