// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_dem.hpp"

#include <fmt/core.h>

#include <cmath>

#include <string_view>

#include "damping_check/yade_version_lines.hpp"
#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

namespace {

// YADE (not run by scenes): the lines for the yade on PATH, as `dem --code yade` prints them. On a YADE that
// cannot express the law (no vn, e.g. Debian's 2023.02a) those are the constant-ε lines with the ε they
// really give, and the report names the version that takes the exact law and shows its lines.
// Returns the report's words on the version.
std::string target_installed_yade(const Material& material, const dem::DampingSource& damping,
                                  const scene::DemTask& task, double tolerance, dem::CodeComparison& c) {
  dem::LinesRequest request;
  request.code = task.code;
  request.end = task.end;
  request.material = material;
  request.damping = damping;
  request.speeds_m_s = task.speeds;
  request.tolerance = tolerance;
  request.friction = task.friction;
  dem::LinesResult r = dem::check_lines(request);
  const dem::TargetedYade yade = dem::installed_yade_or_newest();
  damping_check::target_yade_version(r, yade.version, tolerance);
  c.deck = r.deck;
  c.predicted_eps.clear();
  for (const dem::SpeedEps& e : r.eps) c.predicted_eps.push_back(e.eps);
  std::string words = fmt::format("The yade lines are for YADE {} ({}).", yade.version.text, yade.source);
  if (r.yade_exact_deck) {
    words += fmt::format(
        " YADE {} cannot express this law: the lines above give the eps of the table, the same at every "
        "speed. On YADE 2024.02a or later these lines give the law itself:\n\n```\n",
        yade.version.text);
    for (const auto& line : r.yade_exact_deck->lines) words += line + "\n";
    words += "```\n";
  }
  return words + "\n";
}

}  // namespace

DemSection dem_section(const scene::Scene& scene, const scene::DemTask& task) {
  const dem::Code code = task.code;
  const dem::CodeEntry& entry = dem::code_entry(code);
  const Material& material = scene.materials.at(task.material);
  DemSection s;
  std::string program;
  if (task.run_code && entry.scene_runs) {
    program = dem::dem_program(code);
    if (program.empty()) {
      s.warnings.push_back(
          fmt::format("{} is not installed (scripts/setup installs it): not run", entry.name));
    }
  }
  // Without a calibration the material's own A.
  const dem::DampingSource damping{
      task.eps ? std::nullopt : std::optional<double>(material_constants(material).dissipative_constant_s),
      task.eps, task.velocity_m_s};
  dem::CodeComparison c = dem::compare_with_code(code, material, damping, task.end, task.speeds,
                                                 task.friction, scene.tolerance, scene.method, program);
  std::string yade_words;
  if (!std::string_view(entry.version_query).empty())
    yade_words = target_installed_yade(material, damping, task, scene.tolerance, c);
  const dem::Deck& deck = c.deck;
  const double a = c.dissipative_constant_s;
  const std::vector<double>& predicted = c.predicted_eps;
  const bool ran = c.measured.has_value();
  const std::string measured_column = fmt::format("eps_{}", dem::code_name(code));
  s.code_run = ran                                 ? (c.measured->failure.empty() ? "ok" : "failed")
               : task.run_code && entry.scene_runs ? "not installed"
                                                   : "not asked";
  if (ran && !c.measured->failure.empty()) {
    s.code_failure = c.measured->failure;
    s.warnings.push_back(
        fmt::format("the {} run failed: {}; the rows marked failed in {}_run have no eps of "
                    "the code",
                    entry.name, s.code_failure, dem::code_name(code)));
  }
  // A row the code measured: it exited 0 and printed this row's ε.
  const auto row_ok = [&](std::size_t i) {
    return c.measured->exited_ok && std::isfinite(c.measured->extrapolated[i]);
  };
  s.csv = ran ? fmt::format("velocity_m_s,eps_restitution,{},rel_diff,{}_run\n", measured_column,
                            dem::code_name(code))
              : "velocity_m_s,eps_restitution\n";
  for (std::size_t i = 0; i < task.speeds.size(); ++i) {
    s.csv += fmt::format("{:.17g},{:.17g}", task.speeds[i], predicted[i]);
    if (ran) {
      s.csv += fmt::format(",{:.17g},{:.17g},{}", c.measured->extrapolated[i], c.relative_difference[i],
                           row_ok(i) ? "ok" : "failed");
    }
    s.csv += "\n";
  }
  s.plot_args = {"--x",      "velocity_m_s", "--y",      "eps_restitution",
                 "--xscale", "log",          "--ylabel", R"($\varepsilon$)"};
  if (ran) {
    s.plot_args.insert(
        s.plot_args.end(),
        {"--points", measured_column, "--error", "rel_diff", "--error-label",
         R"($|\varepsilon_\mathrm{code} - \varepsilon| / \min(\varepsilon, 1 - \varepsilon)$)"});
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
  if (!s.code_failure.empty())
    md += fmt::format("**The {} run failed**: {}.\n\n", entry.name, s.code_failure);
  if (ran) {
    md += fmt::format(
        "{} ran the lines above at dt = T/2000 and T/20000 (T the natural time of the fastest collision); "
        "the "
        "column is the Richardson extrapolation (10 eps_fine - eps_coarse)/9.\n\n",
        dem::code_name(code));
  }
  md += yade_words;
  return s;
}

}  // namespace restitution::cli
