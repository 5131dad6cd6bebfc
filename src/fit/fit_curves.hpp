// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Each converged law's ε(v) over the data's speeds at its best parameter and at the bounds of its 95 %
// interval: the curves and bands scripts/plots/fit_data.py draws for `fit-data --plot` and a scene's [[fit]].
#include <cstddef>
#include <vector>

#include "restitution/fit.hpp"

namespace restitution {

inline constexpr int kFitCurvePoints = 101;  // speeds of the curves, log-spaced over the data's

struct FitCurve {
  std::size_t fit = 0;      // the index of its law in FitResult::fits
  std::vector<double> eps;  // at the best parameter
  // The 95 % band's edges: ε decreases with the parameter, so the interval's upper bound gives the lower
  // edge. NaN where that bound lies at the edge of the checked range.
  std::vector<double> band_low, band_high;
};

struct FitCurves {
  std::vector<double> velocity_m_s;  // kFitCurvePoints from the data's slowest to its fastest speed [m/s]
  std::vector<FitCurve> curves;      // one per converged fit, in the order of FitResult::fits
};

// The solves of the speed-independent laws take `options`' tolerance and method (one solve per parameter).
FitCurves fit_curves(const FitData& data, const FitResult& result, const FitOptions& options);

}  // namespace restitution
