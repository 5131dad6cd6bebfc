// SPDX-License-Identifier: BSD-3-Clause
// A [[trajectory]]'s table, figure, report paragraph and summary.json object.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "cli/scene/scene_planned_sections.hpp"
#include "cli/scene/scene_tables.hpp"

namespace restitution::cli {

void write_trajectory_section(const scene::Scene& /*scene*/, const scene::Trajectory& tr,
                              const scene::TrajectoryOutcome& outcome, SectionOutput& out) {
  const scene::PlannedPoint& p = outcome.point;
  const CollisionResult& r = outcome.result;
  const Table t = trajectory_table(outcome);
  std::string report;
  JsonWriter& json = out.summary();
  out.file(tr.name + ".csv", t.csv());
  std::vector<std::string> marks;
  for (const CollisionEnd e : tr.ends.members()) {
    const auto& end = r[e];
    marks.push_back(fmt::format("{}:{:.17g}", end_name(e), end->tau));
  }
  report += fmt::format("## {}\n\n", tr.title);
  report += out.plot("scene_trajectory", tr.name, {"--ends", join(marks)});
  report += fmt::format(
      "Computed: the trajectory x, x', x'' of one {} collision at ζ = {} ({} points in `{}.csv`, natural "
      "units). "
      "Maximal compression x = {} at τ = {}.\n\n",
      law_name(tr.law), report_number(p.parameter), t.rows.size(), tr.name,
      report_number(r.max_compression.x), report_number(r.max_compression.tau));
  report += "| end | τ_c | ε | x(τ_c) |\n|---|---|---|---|\n";
  json.key(tr.name).begin_object();
  json.field("kind", "trajectory");
  if (tr.law != LawKind::viscoelastic_hertz) json.field("law", law_name(tr.law));
  json.field("zeta", p.parameter).field("points", static_cast<long>(t.rows.size()));
  for (const CollisionEnd e : tr.ends.members()) {
    const EndResult& end = *r[e];
    report += fmt::format("| {} | {} | {} | {} |\n", end_name(e), report_number(end.tau),
                          report_number(end.eps), report_number(end.x));
    json.key(end_key(e)).begin_object();
    json.field("tau", end.tau).field("eps", end.eps).field("x", end.x);
    json.end_object();
  }
  json.end_object();
  report +=
      "\nThe delayed-recovery end (force zero, ζx' + x = 0) comes first; integrating on to the naive end "
      "(x = 0) lets the formula's attractive force act (x'' > 0), the 2008 paper's Fig. 3.\n\n";
  out.report(report);
}

}  // namespace restitution::cli
