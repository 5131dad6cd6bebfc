// SPDX-License-Identifier: BSD-3-Clause
// A [[dashpot]]'s table, figure, report paragraph and summary.json object.
#include <fmt/core.h>

#include <string>
#include <vector>

#include "cli/scene/scene_planned_sections.hpp"
#include "cli/scene/scene_tables.hpp"

namespace restitution::cli {

void write_dashpot_section(const scene::Scene& scene, const scene::DashpotCheck& d,
                           const scene::DashpotOutcome& outcome, SectionOutput& out) {
  const Table t = dashpot_table(d, outcome);
  std::string report;
  JsonWriter& json = out.summary();
  out.file(d.name + ".csv", t.csv());
  report += fmt::format("## {}\n\n", d.title);
  std::vector<std::string> numeric;
  std::vector<std::string> exact;
  std::vector<std::string> errors;
  for (const CollisionEnd e : d.ends.members()) {
    numeric.push_back(std::string(end_key(e)) + "_eps");
    exact.push_back(std::string(end_key(e)) + "_eps_exact");
    errors.push_back(std::string(end_key(e)) + "_relative_error");
  }
  report += out.plot("scene_xy", d.name,
                     {"--x", "damping_ratio", "--points", join(numeric), "--y", join(exact), "--error",
                      join(errors), "--error-label",
                      R"($|\varepsilon - \varepsilon_\mathrm{exact}| / \min(\varepsilon, 1 - \varepsilon)$)",
                      "--ylabel", R"($\varepsilon$)", "--yscale", "log"});
  report += fmt::format(
      "Computed: the linear dash-pot x'' + 2r x' + x = 0 at {} damping ratios against its closed forms "
      "(ε = exp(-r τ_c); naive ωτ_c = π for r < 1, delayed recovery tan ωτ_c = 2rω/(2r²-1)). The error is "
      "|ε - ε_exact| / min(ε_exact, 1 - ε_exact), which the tolerance {} bounds.\n\n",
      t.rows.size(), report_number(scene.tolerance));
  json.key(d.name).begin_object();
  json.field("kind", "dashpot");
  for (const CollisionEnd e : d.ends.members()) {
    const std::string c = std::string(end_key(e)) + "_relative_error";  // the CSV column
    const double worst = outcome.max_relative_error[e];
    report += fmt::format("* largest {}: {:.3g}\n", c, worst);
    json.field("max_" + c, worst);
  }
  json.end_object();
  report += "\n";
  out.report(report);
}

}  // namespace restitution::cli
