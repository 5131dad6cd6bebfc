// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/grid.hpp"

#include <limits>

namespace restitution::damping_check {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The actual ε of `recipe` for each clamp at each speed (one value when speed-independent).
ByClamp actual(Recipe recipe, double eps, const std::vector<double>& speeds, const GridRequest& g,
               CollisionSolver& solver) {
  CheckRequest request;
  request.recipe = recipe;
  request.eps_requested = eps;
  request.reference_velocity_m_s = g.reference_velocity_m_s;
  request.speeds_m_s = speeds;
  request.tolerance = g.tolerance;
  const CheckResult r = check_recipe(request, solver);
  ByClamp by_clamp;
  for (const CheckPoint& p : r.points)
    (p.clamp == Clamp::on ? by_clamp.on : by_clamp.off).push_back(p.actual_eps.value_or(kNaN));
  return by_clamp;
}

// value / reference - 1 for each value (NaN stays NaN).
std::vector<double> ratios_minus_one(const std::vector<double>& values, double reference) {
  std::vector<double> out;
  out.reserve(values.size());
  for (const double v : values) out.push_back(v / reference - 1.0);
  return out;
}

}  // namespace

GridResult check_grid(const GridRequest& request, CollisionSolver& solver) {
  const GridRequest& g = request;
  const double v_ref = g.reference_velocity_m_s;
  GridResult out;
  out.findings_speeds_m_s = {v_ref / 10.0, v_ref, 10.0 * v_ref};
  const std::vector<double> findings_speeds(out.findings_speeds_m_s.begin(), out.findings_speeds_m_s.end());
  for (const Recipe recipe : g.recipes) {
    RecipeGrid grid;
    grid.recipe = recipe;
    grid.speed_independent = recipe_setting(recipe, 0.5, g.tolerance, solver).speed_independent();
    for (const double e : g.eps) {
      const ByClamp& at_ref = grid.at_reference.emplace_back(actual(recipe, e, {v_ref}, g, solver));
      grid.recipe_error_at_calibration_speed.push_back(
          {ratios_minus_one(at_ref.on, e), ratios_minus_one(at_ref.off, e)});
    }
    if (!grid.speed_independent) {
      for (std::size_t k = 0; k < g.eps.size(); ++k) {
        const ByClamp a = actual(recipe, g.eps[k], g.speeds_m_s, g, solver);
        const ByClamp& at_ref = grid.at_reference[k];
        grid.speed_dependence.push_back(
            {ratios_minus_one(a.on, at_ref.on.front()), ratios_minus_one(a.off, at_ref.off.front())});
      }
    }
    for (const double e : kFindingsEps)
      grid.findings.push_back(actual(recipe, e, findings_speeds, g, solver));
    out.recipes.push_back(std::move(grid));
  }
  return out;
}

}  // namespace restitution::damping_check
