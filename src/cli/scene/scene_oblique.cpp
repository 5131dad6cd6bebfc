// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_oblique.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "cli/common/parse_errors.hpp"
#include "cli/oblique/oblique_sweep.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

// One sentence per model: e_t's range, how many impacts slide, the sticking limit where it was computed (the
// plot's reference: not with plot = false), the impacts that failed.
std::string model_summary(const scene::ObliqueModelRun& run, bool sticking_limit) {
  std::string limit;
  if (sticking_limit) {
    limit = run.sticking.failure.empty()
                ? fmt::format("; sticking limit e_t(μ → ∞) = {:.6g}", run.sticking.tangential_restitution)
                : fmt::format("; sticking limit not computed ({})", one_line(run.sticking.failure));
  }
  std::string failures;
  for (const ObliqueImpact& i : run.impacts) {
    if (!i.solved()) {
      failures += fmt::format(" Not solved (status failed in the CSV) at {:g}°, spin {:g} rad/s: {}.",
                              i.angle_deg, i.initial_spin_rad_s, one_line(i.failure));
    }
  }
  return fmt::format(
      "* {}: e_t from {:.6g} to {:.6g}; {} of {} impacts slide for at least 99 % of the contact{}.{}\n",
      tangential_name(run.setup.tangential.kind), run.lowest_et, run.highest_et, run.sliding,
      run.impacts.size(), limit, failures);
}

// The report's paragraph: which wall, ε's range, χ, then one sentence per model.
std::string oblique_markdown(const scene::ObliqueTask& task, const scene::ObliqueOutcome& o) {
  const scene::ObliqueModelRun& first = o.runs.front();
  const std::string wall =
      !task.inputs.wall ? "two spheres"
      : first.setup.rigid_wall
          ? "a sphere on a rigid wall"
          : fmt::format("a sphere on a wall of Y = {:g} Pa, ν = {:g}", *task.inputs.wall_young_modulus_pa,
                        *task.inputs.wall_poisson_ratio);
  std::string markdown = fmt::format(
      "Oblique impacts (docs/oblique.md) of {} of [materials.{}] at {:g} m/s, μ = {:g}, {} angle(s) from "
      "{}° to {}°, {} initial spin(s); normal restitution ε (head-on at the normal speed v cos θ, {} end) "
      "from {:.10g} to {:.10g}; Maw's χ = {:.6g} (gross slip: ψ₂ = ψ₁ − 2(1 + ε)χ, drawn with ε = {:.10g} of "
      "the first impact).\n\n",
      wall, task.material, task.inputs.speed_m_s, *task.inputs.friction, task.inputs.angles_deg.size(),
      *std::min_element(task.inputs.angles_deg.begin(), task.inputs.angles_deg.end()),
      *std::max_element(task.inputs.angles_deg.begin(), task.inputs.angles_deg.end()),
      task.inputs.spins_rad_s.size(), task.inputs.end, o.eps_low, o.eps_high, o.maw_chi, o.first_eps);
  for (const scene::ObliqueModelRun& run : o.runs) markdown += model_summary(run, o.plotted);
  markdown += fmt::format("\nEvery impact is a row of `{}.csv`.\n\n", task.name);
  return markdown;
}

void write_summary(JsonWriter& json, const scene::ObliqueTask& task, const scene::ObliqueOutcome& o) {
  json.key("oblique_" + task.name).begin_object();
  json.field("csv", task.name + ".csv").field("impacts", static_cast<long>(o.runs.front().impacts.size()));
  json.field("normal_restitution", o.runs.front().impacts.front().result.normal_restitution);
  json.field("maw_chi", o.maw_chi);
  json.key("sticking_restitution").begin_object();
  for (const scene::ObliqueModelRun& run : o.runs) {
    json.field(tangential_name(run.setup.tangential.kind), run.sticking.tangential_restitution);
  }
  json.end_object().end_object();
}

}  // namespace

void write_oblique_section(const scene::Scene& /*scene*/, const scene::ObliqueTask& task,
                           const scene::ObliqueOutcome& o, SectionOutput& out) {
  std::string csv = oblique_csv_header_with_model() + "\n";
  for (const scene::ObliqueModelRun& run : o.runs) {
    csv += oblique_csv_rows(run.impacts, tangential_name(run.setup.tangential.kind));
  }
  out.file(task.name + ".csv", csv);
  for (const scene::ObliqueModelRun& run : o.runs) {
    if (run.failed > 0) {
      out.warn(fmt::format("{}: {} of {} impacts of {} failed (status failed in {}.csv; the report says why)",
                           task.name, run.failed, run.impacts.size(),
                           tangential_name(run.setup.tangential.kind), task.name));
    }
  }
  out.report(fmt::format("## {}\n\n", task.title));
  if (o.plotted && !std::isnan(o.first_eps)) {
    std::vector<MawModel> models;
    for (const scene::ObliqueModelRun& run : o.runs) {
      models.push_back(
          {run.setup.tangential.kind, run.sticking.tangential_restitution, run.sticking.failure});
    }
    out.report(
        out.plot("oblique_maw", task.name, maw_plot_arguments(o.runs.front().setup, o.first_eps, models)));
  }
  out.report(oblique_markdown(task, o));
  write_summary(out.summary(), task, o);
}

}  // namespace restitution::cli
