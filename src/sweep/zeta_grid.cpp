// SPDX-License-Identifier: BSD-3-Clause
// The ζ values of a sweep.
#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "restitution/errors.hpp"
#include "restitution/sweep.hpp"

namespace restitution {
namespace {

void require_bound(double value, const char* variable, const char* bound) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{}-{} must be a finite number >= 0, got {}", variable, bound, value));
  }
}

}  // namespace

std::vector<double> zeta_values(const ZetaGrid& grid) {
  const char* v = grid.variable;
  require_bound(grid.zeta_min, v, "min");
  require_bound(grid.zeta_max, v, "max");
  if (grid.zeta_min > grid.zeta_max) {
    throw InvalidInput(
        fmt::format("{0}-min ({1}) must not exceed {0}-max ({2})", v, grid.zeta_min, grid.zeta_max));
  }
  if (grid.points < 1 || grid.points > kMaxSweepPoints) {
    throw InvalidInput(fmt::format("points must lie in [1, {}], got {}", kMaxSweepPoints, grid.points));
  }
  if (grid.points == 1 && grid.zeta_min != grid.zeta_max) {
    throw InvalidInput(fmt::format("points = 1 needs {0}-min = {0}-max (one point cannot span a range)", v));
  }
  if (grid.logarithmic && grid.zeta_min == 0.0) {
    throw InvalidInput(fmt::format("logarithmic spacing needs {}-min > 0", v));
  }
  std::vector<double> zetas(grid.points);
  const auto last = static_cast<double>(grid.points - 1);
  const double lo = grid.logarithmic ? std::log(grid.zeta_min) : grid.zeta_min;
  const double hi = grid.logarithmic ? std::log(grid.zeta_max) : grid.zeta_max;
  for (std::size_t i = 0; i < grid.points; ++i) {
    // Interpolating from both ends keeps the end points exact and the spacing symmetric.
    const double f = last == 0.0 ? 0.0 : static_cast<double>(i) / last;
    const double t = (1.0 - f) * lo + f * hi;
    // Rounding (and exp of a log) may step a hair past the range: an interior point of the grid 100..100 came
    // out as 100.00000000000001, which a bound like the Taylor naive end's ζ <= 100 then refused.
    zetas[i] = std::clamp(grid.logarithmic ? std::exp(t) : t, grid.zeta_min, grid.zeta_max);
  }
  zetas.front() = grid.zeta_min;
  zetas.back() = grid.zeta_max;
  return zetas;
}

std::vector<double> evenly_spaced(double from, double to, std::size_t n) {
  std::vector<double> values(n, from);
  const auto last = static_cast<double>(n - 1);
  for (std::size_t i = 1; i + 1 < n; ++i) {
    const auto k = static_cast<double>(i);
    double value = (from * (last - k) + to * k) / last;
    // Ends near the largest doubles overflow the weighted sum: interpolate from the lower end there.
    if (!std::isfinite(value)) value = from + (to - from) / last * k;
    values[i] = std::clamp(value, std::min(from, to), std::max(from, to));
  }
  if (n > 1) values.back() = to;
  return values;
}

}  // namespace restitution
