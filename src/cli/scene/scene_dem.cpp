// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_dem.hpp"

#include <fmt/core.h>

#include <cmath>
#include <string>
#include <vector>

#include "dem/dem_codes.hpp"

namespace restitution::cli {

namespace {

struct DemSection {
  std::string markdown;  // the report text after the plot
  std::string csv;       // velocity_m_s, eps_restitution[, eps_<code>, rel_diff, <code>_run (ok | failed)]
  std::vector<std::string> plot_args;  // for scripts/plots/scene_xy.py after CSV and PNG
  std::vector<std::string> warnings;   // e.g. the code is not installed, or its run failed
  std::string code_run;                // "ok", "failed", "not installed" or "not asked" (summary.json)
  std::string code_failure;            // what went wrong when it failed (dem::DemMeasurement::failure)
};

// The report's words on the YADE version the lines are for, and the law's own lines for a later YADE when
// the targeted one cannot express it.
std::string yade_words(const scene::DemYadeTarget& target) {
  std::string words =
      fmt::format("The yade lines are for YADE {} ({}).", target.yade.version.text, target.yade.source);
  if (target.exact_deck) {
    words += fmt::format(
        " YADE {} cannot express this law: the lines above give the eps of the table, the same at every "
        "speed. On YADE 2024.02a or later these lines give the law itself:\n\n```\n",
        target.yade.version.text);
    for (const auto& line : target.exact_deck->lines) words += line + "\n";
    words += "```\n";
  }
  return words + "\n";
}

DemSection dem_section(const scene::DemTask& task, const scene::DemOutcome& outcome) {
  const dem::Code code = dem::code_from_name(task.inputs.code);
  const dem::CodeEntry& entry = dem::code_entry(code);
  DemSection s;
  if (outcome.code_not_installed) {
    s.warnings.push_back(fmt::format("{} is not installed (scripts/setup installs it): not run", entry.name));
  }
  const dem::CodeComparison& c = outcome.comparison;
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
  for (std::size_t i = 0; i < task.inputs.speeds_m_s.size(); ++i) {
    s.csv += fmt::format("{:.17g},{:.17g}", task.inputs.speeds_m_s[i], predicted[i]);
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
  md += fmt::format("{} lines for material `{}`, A = {:.10g} s, {} end{}:\n\n```\n", dem::code_name(code),
                    task.material, a, task.inputs.end,
                    task.inputs.eps ? fmt::format(" (calibrated to eps = {} at {} m/s)", *task.inputs.eps,
                                                  *task.inputs.velocity_m_s)
                                    : "");
  for (const auto& p : deck.parameters) md += fmt::format("{} = {}: {}\n", p.name, p.value, p.meaning);
  for (const auto& line : deck.lines) md += line + "\n";
  md += "```\n\n";
  for (const auto& note : deck.notes) md += "* " + note + "\n";
  md += "\n| v [m/s] | eps (restitution) |";
  md += ran ? fmt::format(" eps ({}, extrapolated) | difference / min(eps, 1 - eps) |\n|---|---|---|---|\n",
                          dem::code_name(code))
            : "\n|---|---|\n";
  for (std::size_t i = 0; i < task.inputs.speeds_m_s.size(); ++i) {
    md += fmt::format("| {:g} | {:.10f} |", task.inputs.speeds_m_s[i], predicted[i]);
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
  if (outcome.yade) md += yade_words(*outcome.yade);
  return s;
}

}  // namespace

void write_dem_section(const scene::Scene& /*scene*/, const scene::DemTask& task,
                       const scene::DemOutcome& outcome, SectionOutput& out) {
  DemSection section = dem_section(task, outcome);
  out.file(task.name + ".csv", section.csv);
  out.report(fmt::format("## {}\n\n", task.title));
  out.report(out.plot("scene_xy", task.name, section.plot_args));
  out.report(section.markdown);
  for (auto& w : section.warnings) out.warn(fmt::format("{}: {}", task.name, w));
  JsonWriter& json = out.summary();
  json.key("dem_" + task.name).begin_object();
  json.field("code", task.inputs.code).field("code_run", section.code_run);
  if (!section.code_failure.empty()) json.field("code_failure", section.code_failure);
  json.end_object();
}

}  // namespace restitution::cli
