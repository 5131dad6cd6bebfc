// SPDX-License-Identifier: BSD-3-Clause
// The [[calibration]] sections of a scene: one table of the report and the summary's "calibrations" array,
// after the sections written in the file's order.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "cli/common/result_json.hpp"
#include "cli/scene/scene_planned_sections.hpp"
#include "cli/scene/scene_tables.hpp"
#include "restitution/calibration.hpp"

namespace restitution::cli {
namespace {

// The row of one calibration in the report's table and its object in summary.json.
void write_calibration(const scene::CalibrationTask& task, const Calibration& c, std::string& report,
                       JsonWriter& json) {
  const bool hertz = task.law == LawKind::viscoelastic_hertz;
  const std::string name = hertz ? task.name : fmt::format("{} ({})", task.name, law_name(task.law));
  report += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", name, report_number(task.eps),
                        report_number(task.velocity_m_s), end_name(task.end), report_number(c.zeta),
                        hertz ? report_number(c.beta) : "—", report_number(c.eps_at_zeta),
                        hertz ? report_number(c.characteristic_velocity_m_s) : "—",
                        c.dissipative_constant_s ? report_number(*c.dissipative_constant_s) : "—");
  json.begin_object();
  json.field("name", task.name).field("eps", task.eps).field("velocity_m_s", task.velocity_m_s);
  if (!hertz) json.field("law", law_name(task.law)).field(parameter_key(task.law), c.parameter);
  json.field("end", end_name(task.end)).field("zeta", c.zeta);
  if (hertz) json.field("beta", c.beta);
  json.field("eps_at_zeta", c.eps_at_zeta);
  if (hertz) json.field("characteristic_velocity_m_s", c.characteristic_velocity_m_s);
  if (c.dissipative_constant_s) json.field("dissipative_constant_s", *c.dissipative_constant_s);
  json.end_object();
}

}  // namespace

void write_calibrations(const scene::Scene& /*scene*/, const std::vector<SectionResult>& sections,
                        SectionOutput& out) {
  if (sections.empty()) return;
  std::string report =
      "## Calibration\n\n"
      "β from a measured ε at one impact speed (root finding on ζ with the solver); A = β / ((3/2) "
      "k^(2/5)) "
      "for a material; the 1999 paper's g* = (C1 β)^(-5).\n\n"
      "| name | ε | v [m/s] | end | ζ | β [s^(1/5) m^(-1/5)] | ε(ζ) re-solved | g* [m/s] | A [s] |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  JsonWriter& json = out.summary();
  json.key("calibrations").begin_array();
  for (const SectionResult& s : sections) {
    write_calibration(std::any_cast<const scene::CalibrationTask&>(s.section->task),
                      std::any_cast<const scene::CalibrationOutcome&>(*s.outcome).calibration, report, json);
  }
  json.end_array();
  report += "\n";
  out.report(report);
}

}  // namespace restitution::cli
