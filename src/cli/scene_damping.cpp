#include "cli/scene_damping.hpp"

#include <fmt/core.h>

#include <cmath>
#include <limits>
#include <string>

#include "damping_check/check.hpp"

namespace restitution::cli {
namespace {

using damping_check::CheckRequest;
using damping_check::Clamp;
using damping_check::Recipe;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The actual ε of `recipe` for each clamp (on, off) at each speed (one value when speed-independent).
std::vector<std::vector<double>> actual(Recipe recipe, double eps, const std::vector<double>& speeds,
                                        double reference_velocity, double tolerance,
                                        CollisionSolver& solver) {
  CheckRequest request;
  request.recipe = recipe;
  request.eps_requested = eps;
  request.reference_velocity_m_s = reference_velocity;
  request.speeds_m_s = speeds;
  request.tolerance = tolerance;
  const damping_check::CheckResult r = damping_check::check_recipe(request, solver);
  std::vector<std::vector<double>> by_clamp(2);
  for (const auto& p : r.points)
    by_clamp[p.clamp == Clamp::on ? 0 : 1].push_back(p.actual_eps.value_or(kNaN));
  return by_clamp;
}

std::string cell(const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    text += (text.empty() ? "" : " / ") + (std::isfinite(v) ? fmt::format("{:.4f}", v) : std::string("none"));
  }
  return text;
}

}  // namespace

DampingSection damping_section(const scene::Scene& scene, const scene::DampingCheckTask& task) {
  CollisionSolver solver;
  const double v_ref = task.velocity_m_s;
  DampingSection s;

  // Requested against actual ε at the reference speed, every recipe and clamp.
  DampingPlot map;
  map.name = task.name;
  map.script = "scene_xy";
  map.csv = "requested_eps";
  std::vector<std::string> columns;
  for (const std::string& name : task.recipes) {
    for (const char* clamp : {"on", "off"}) columns.push_back(fmt::format("{}_clamp_{}", name, clamp));
  }
  for (const auto& c : columns) map.csv += "," + c;
  map.csv += "\n";
  for (double e : task.eps) {
    map.csv += fmt::format("{:.17g}", e);
    for (const std::string& name : task.recipes) {
      const auto a =
          actual(damping_check::recipe_from_name(name), e, {v_ref}, v_ref, scene.tolerance, solver);
      map.csv += fmt::format(",{:.17g},{:.17g}", a[0].front(), a[1].front());
    }
    map.csv += "\n";
  }
  // Clamp on solid, clamp off dashed, actual = requested as points.
  std::string on;
  std::string off;
  for (const auto& c : columns) {
    std::string& list = c.ends_with("_on") ? on : off;
    list += (list.empty() ? "" : ",") + c;
  }
  map.args = {"--x",      "requested_eps",
              "--y",      on,
              "--dashed", off,
              "--points", "requested_eps",
              "--title",  task.title,
              "--xlabel", "requested eps",
              "--ylabel", fmt::format("actual eps (speed-dependent recipes at {:g} m/s)", v_ref)};
  map.caption = fmt::format(
      "Actual against requested ε for {} recipes, clamp on (force clamped at zero: the delayed-recovery end) "
      "and off (the naive end, dashed); the points are actual = requested. A missing point without the clamp "
      "is "
      "an overdamped Tsuji member (ζ >= sqrt(5)): the overlap never returns to 0.\n\n",
      task.recipes.size());
  s.plots.push_back(map);

  // Relative error over requested ε × speed for each speed-dependent recipe.
  for (const std::string& name : task.recipes) {
    const Recipe recipe = damping_check::recipe_from_name(name);
    if (damping_check::recipe_setting(recipe, 0.5, scene.tolerance, solver).speed_independent()) continue;
    DampingPlot errors;
    errors.name = fmt::format("{}_{}_error", task.name, name);
    errors.script = "damping_heatmap";
    errors.csv = "requested_eps,velocity_m_s,relative_error_clamp_on,relative_error_clamp_off\n";
    for (double e : task.eps) {
      const auto a = actual(recipe, e, task.speeds, v_ref, scene.tolerance, solver);
      for (std::size_t i = 0; i < task.speeds.size(); ++i) {
        errors.csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g}\n", e, task.speeds[i], (a[0][i] - e) / e,
                                  (a[1][i] - e) / e);
      }
    }
    errors.args = {"--title",
                   fmt::format("{}: (actual - requested) / requested, set up at {:g} m/s", name, v_ref)};
    errors.caption = fmt::format(
        "`{}` is exact nowhere but along its set-up speed {:g} m/s (and only as far as "
        "its formula is exact there).\n\n",
        name, v_ref);
    s.plots.push_back(errors);
  }

  // The findings table.
  const std::vector<double> requested{0.3, 0.5, 0.8, 0.95};
  const std::vector<double> speeds{v_ref / 10.0, v_ref, 10.0 * v_ref};
  std::string& md = s.findings;
  md += fmt::format(
      "Actual ε for requested ε; speed-dependent recipes at v = {:g} / {:g} / {:g} m/s (set up at {:g} "
      "m/s).\n\n"
      "| recipe | clamp |",
      speeds[0], speeds[1], speeds[2], v_ref);
  for (double e : requested) md += fmt::format(" ε_req = {:g} |", e);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < requested.size(); ++i) md += "---|";
  md += "\n";
  for (const std::string& name : task.recipes) {
    const Recipe recipe = damping_check::recipe_from_name(name);
    std::vector<std::vector<std::vector<double>>> by_eps;
    by_eps.reserve(requested.size());
    for (double e : requested) by_eps.push_back(actual(recipe, e, speeds, v_ref, scene.tolerance, solver));
    for (int c = 0; c < 2; ++c) {
      md += fmt::format("| {} | {} |", name, c == 0 ? "on" : "off");
      for (const auto& a : by_eps) md += " " + cell(a[c]) + " |";
      md += "\n";
    }
  }
  md += "\n";
  return s;
}

}  // namespace restitution::cli
