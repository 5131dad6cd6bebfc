// The ζ values of a sweep.
#include <fmt/core.h>

#include <cmath>

#include "restitution/errors.hpp"
#include "sweep/sweep.hpp"

namespace restitution {
namespace {

void require_bound(double value, const char* name) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(fmt::format("{} must be a finite number >= 0, got {}", name, value));
  }
}

}  // namespace

std::vector<double> zeta_values(const ZetaGrid& grid) {
  require_bound(grid.zeta_min, "zeta-min");
  require_bound(grid.zeta_max, "zeta-max");
  if (grid.zeta_min > grid.zeta_max) {
    throw InvalidInput(
        fmt::format("zeta-min ({}) must not exceed zeta-max ({})", grid.zeta_min, grid.zeta_max));
  }
  if (grid.points < 1 || grid.points > kMaxSweepPoints) {
    throw InvalidInput(fmt::format("points must lie in [1, {}], got {}", kMaxSweepPoints, grid.points));
  }
  if (grid.points == 1 && grid.zeta_min != grid.zeta_max) {
    throw InvalidInput("points = 1 needs zeta-min = zeta-max (one point cannot span a range)");
  }
  if (grid.logarithmic && grid.zeta_min == 0.0) {
    throw InvalidInput("logarithmic spacing needs zeta-min > 0");
  }
  std::vector<double> zetas(grid.points);
  const auto last = static_cast<double>(grid.points - 1);
  const double lo = grid.logarithmic ? std::log(grid.zeta_min) : grid.zeta_min;
  const double hi = grid.logarithmic ? std::log(grid.zeta_max) : grid.zeta_max;
  for (std::size_t i = 0; i < grid.points; ++i) {
    // Interpolating from both ends keeps the end points exact and the spacing symmetric.
    const double f = last == 0.0 ? 0.0 : static_cast<double>(i) / last;
    const double t = (1.0 - f) * lo + f * hi;
    zetas[i] = grid.logarithmic ? std::exp(t) : t;
  }
  zetas.front() = grid.zeta_min;
  zetas.back() = grid.zeta_max;
  return zetas;
}

}  // namespace restitution
