// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene_dem.hpp"

#include <fmt/core.h>

#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

DemSection dem_section(const scene::Scene& scene, const scene::DemTask& task) {
  const dem::Code code = dem::code_from_name(task.code);
  const Material& material = scene.materials.at(task.material);
  DemSection s;
  std::string program;
  if (task.run_code && (code == dem::Code::lammps || code == dem::Code::liggghts)) {
    program = dem::dem_program(code);
    if (program.empty()) {
      s.warnings.push_back(
          fmt::format("{} is not installed (scripts/setup installs it): not run", task.code));
    }
  }
  // Without a calibration the material's own A.
  const dem::DampingSource damping{
      task.eps ? std::nullopt : std::optional<double>(material_constants(material).dissipative_constant_s),
      task.eps, task.velocity_m_s};
  const dem::CodeComparison c = dem::compare_with_code(code, material, damping, task.end, task.speeds,
                                                       task.friction, scene.tolerance, scene.method, program);
  const dem::Deck& deck = c.deck;
  const double a = c.dissipative_constant_s;
  const std::vector<double>& predicted = c.predicted_eps;
  const bool ran = c.measured.has_value();
  const std::string measured_column = fmt::format("eps_{}", dem::code_name(code));
  s.csv = ran ? fmt::format("velocity_m_s,eps_restitution,{},rel_diff\n", measured_column)
              : "velocity_m_s,eps_restitution\n";
  for (std::size_t i = 0; i < task.speeds.size(); ++i) {
    s.csv += fmt::format("{:.17g},{:.17g}", task.speeds[i], predicted[i]);
    if (ran) {
      s.csv += fmt::format(",{:.17g},{:.17g}", c.measured->extrapolated[i], c.relative_difference[i]);
    }
    s.csv += "\n";
  }
  s.plot_args = {"--x",     "velocity_m_s", "--y",      "eps_restitution",      "--xscale", "log",
                 "--title", task.title,     "--xlabel", "impact speed v [m/s]", "--ylabel", "eps"};
  if (ran) {
    s.plot_args.insert(s.plot_args.end(), {"--points", measured_column, "--error", "rel_diff",
                                           "--error-label", "|eps_code - eps| / min(eps, 1 - eps)"});
  }

  std::string& md = s.markdown;
  md += fmt::format(
      "{} lines for material `{}`, A = {:.10g} s, {} end{}:\n\n```\n", dem::code_name(code), task.material, a,
      end_name(task.end),
      task.eps ? fmt::format(" (calibrated to eps = {} at {} m/s)", *task.eps, *task.velocity_m_s) : "");
  for (const auto& p : deck.parameters) md += fmt::format("{} = {}: {}\n", p.name, p.value, p.meaning);
  for (const auto& line : deck.lines) md += line + "\n";
  md += "```\n\n";
  for (const auto& note : deck.notes) md += "* " + note + "\n";
  md += "\n| v [m/s] | eps (restitution) |";
  md += ran ? fmt::format(" eps ({}, extrapolated) | difference / min(eps, 1 - eps) |\n|---|---|---|---|\n",
                          dem::code_name(code))
            : "\n|---|---|\n";
  for (std::size_t i = 0; i < task.speeds.size(); ++i) {
    md += fmt::format("| {:g} | {:.10f} |", task.speeds[i], predicted[i]);
    if (ran) {
      md += fmt::format(" {:.10f} | {:.2e} |", c.measured->extrapolated[i], c.relative_difference[i]);
    }
    md += "\n";
  }
  md += "\n";
  if (ran) {
    md += fmt::format(
        "{} ran the lines above at dt = T/2000 and T/20000 (T the natural time of the fastest collision); "
        "the "
        "column is the Richardson extrapolation (10 eps_fine - eps_coarse)/9.\n\n",
        dem::code_name(code));
  }
  return s;
}

}  // namespace restitution::cli
