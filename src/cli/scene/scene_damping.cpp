// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_damping.hpp"

#include <fmt/core.h>

#include <cmath>
#include <string>

namespace restitution::cli {
namespace {

using damping_check::ByClamp;
using damping_check::RecipeGrid;

std::string cell(const std::vector<double>& values) {
  std::string text;
  for (double v : values) {
    text += (text.empty() ? "" : " / ") + (std::isfinite(v) ? fmt::format("{:.4f}", v) : std::string("none"));
  }
  return text;
}

}  // namespace

DampingSection damping_section(const scene::DampingCheckTask& task, const damping_check::GridResult& grid) {
  const double v_ref = task.inputs.velocity_m_s;
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
  for (std::size_t k = 0; k < task.eps.size(); ++k) {
    map.csv += fmt::format("{:.17g}", task.eps[k]);
    for (const RecipeGrid& r : grid.recipes) {
      const ByClamp& a = r.at_reference[k];
      map.csv += fmt::format(",{:.17g},{:.17g}", a.on.front(), a.off.front());
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
  map.args = {
      "--x",      "requested_eps",
      "--y",      on,
      "--dashed", off,
      "--points", "requested_eps",
      "--ylabel", fmt::format(R"(actual $\varepsilon$ (speed-dependent recipes at {:g} m/s))", v_ref)};
  map.caption = fmt::format(
      "Actual against requested ε for {} recipes, clamp on (force clamped at zero: the delayed-recovery end) "
      "and off (the naive end, dashed); the points are actual = requested. A missing point without the clamp "
      "is "
      "an overdamped Tsuji member (ζ >= sqrt(5)): the overlap never returns to 0.\n\n",
      task.recipes.size());
  s.plots.push_back(map);

  // Per speed-dependent recipe: its own error at the set-up speed (a function of the requested ε alone) and
  // the physical speed dependence ε(v)/ε(v_ref) - 1 over requested ε × speed, kept apart (docs/damping.md).
  for (std::size_t r = 0; r < grid.recipes.size(); ++r) {
    const RecipeGrid& recipe = grid.recipes[r];
    if (recipe.speed_independent) continue;
    const std::string& name = task.recipes[r];
    DampingPlot errors;
    errors.name = fmt::format("{}_{}_error", task.name, name);
    errors.script = "damping_heatmap";
    errors.csv =
        "requested_eps,velocity_m_s,recipe_error_at_calibration_speed_clamp_on,"
        "recipe_error_at_calibration_speed_clamp_off,speed_dependence_clamp_on,speed_dependence_clamp_off\n";
    for (std::size_t k = 0; k < task.eps.size(); ++k) {
      const ByClamp& cal = recipe.recipe_error_at_calibration_speed[k];
      const ByClamp& dep = recipe.speed_dependence[k];
      for (std::size_t i = 0; i < task.speeds.size(); ++i) {
        errors.csv += fmt::format("{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", task.eps[k],
                                  task.speeds[i], cal.on.front(), cal.off.front(), dep.on[i], dep.off[i]);
      }
    }
    errors.caption = fmt::format(
        "`{}`: top, its own error at the set-up speed {:g} m/s, ε(v_ref)/ε_req − 1 (a property of the "
        "recipe's formula); bottom, the physical speed dependence ε(v)/ε(v_ref) − 1 of the law it sets, "
        "which "
        "no ε_req removes. ε(v)/ε_req = (1 + top)(1 + bottom).\n\n",
        name, v_ref);
    s.plots.push_back(errors);
  }

  // The findings table.
  const auto& speeds = grid.findings_speeds_m_s;
  std::string& md = s.findings;
  md += fmt::format(
      "Actual ε for requested ε; speed-dependent recipes at v = {:g} / {:g} / {:g} m/s (set up at {:g} "
      "m/s).\n\n"
      "| recipe | clamp |",
      speeds[0], speeds[1], speeds[2], v_ref);
  for (double e : damping_check::kFindingsEps) md += fmt::format(" ε_req = {:g} |", e);
  md += "\n|---|---|";
  for (std::size_t i = 0; i < damping_check::kFindingsEps.size(); ++i) md += "---|";
  md += "\n";
  for (std::size_t r = 0; r < grid.recipes.size(); ++r) {
    for (const bool clamp_on : {true, false}) {
      md += fmt::format("| {} | {} |", task.recipes[r], clamp_on ? "on" : "off");
      for (const ByClamp& a : grid.recipes[r].findings)
        md += fmt::format(" {} |", cell(clamp_on ? a.on : a.off));
      md += "\n";
    }
  }
  md += "\n";
  return s;
}

void write_damping_check_section(const scene::Scene& /*scene*/, const scene::DampingCheckTask& task,
                                 const damping_check::GridResult& grid, SectionOutput& out) {
  const DampingSection section = damping_section(task, grid);
  out.report(fmt::format("## {}\n\n", task.title));
  for (const DampingPlot& p : section.plots) {
    out.file(p.name + ".csv", p.csv);
    out.report(out.plot(p.script, p.name, p.args));
    out.report(p.caption);
  }
  out.report(section.findings);
}

}  // namespace restitution::cli
