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

std::vector<double> relative_errors(const std::vector<double>& actual, double requested) {
  std::vector<double> errors;
  errors.reserve(actual.size());
  for (const double a : actual) errors.push_back((a - requested) / requested);
  return errors;
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
    for (const double e : g.eps) grid.at_reference.push_back(actual(recipe, e, {v_ref}, g, solver));
    if (!grid.speed_independent) {
      for (const double e : g.eps) {
        const ByClamp a = actual(recipe, e, g.speeds_m_s, g, solver);
        grid.relative_error.push_back({relative_errors(a.on, e), relative_errors(a.off, e)});
      }
    }
    for (const double e : kFindingsEps)
      grid.findings.push_back(actual(recipe, e, findings_speeds, g, solver));
    out.recipes.push_back(std::move(grid));
  }
  return out;
}

}  // namespace restitution::damping_check
