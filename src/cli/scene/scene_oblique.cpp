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

}  // namespace

ObliqueSection oblique_section(const scene::Scene& scene, const scene::ObliqueTask& task) {
  ObliqueSection s;
  s.outcome = scene::run_oblique_section(scene, task);
  const scene::ObliqueOutcome& o = s.outcome;
  s.csv = oblique_csv_header_with_model() + "\n";
  for (const scene::ObliqueModelRun& run : o.runs) {
    s.csv += oblique_csv_rows(run.impacts, tangential_name(run.setup.tangential.kind));
  }
  const scene::ObliqueModelRun& first = o.runs.front();
  if (o.plotted && !std::isnan(o.first_eps)) {
    std::vector<MawModel> models;
    for (const scene::ObliqueModelRun& run : o.runs) {
      models.push_back(
          {run.setup.tangential.kind, run.sticking.tangential_restitution, run.sticking.failure});
    }
    s.plot_args = maw_plot_arguments(first.setup, o.first_eps, models);
  }
  const std::string wall = !task.wall ? "two spheres"
                           : first.setup.rigid_wall
                               ? "a sphere on a rigid wall"
                               : fmt::format("a sphere on a wall of Y = {:g} Pa, ν = {:g}",
                                             *task.wall_young_modulus_pa, *task.wall_poisson_ratio);
  s.markdown = fmt::format(
      "Oblique impacts (docs/oblique.md) of {} of [materials.{}] at {:g} m/s, μ = {:g}, {} angle(s) from "
      "{}° to {}°, {} initial spin(s); normal restitution ε (head-on at the normal speed v cos θ, {} end) "
      "from {:.10g} to {:.10g}; Maw's χ = {:.6g} (gross slip: ψ₂ = ψ₁ − 2(1 + ε)χ, drawn with ε = {:.10g} of "
      "the first impact).\n\n",
      wall, task.material, task.speed_m_s, task.friction, task.angles_deg.size(),
      *std::min_element(task.angles_deg.begin(), task.angles_deg.end()),
      *std::max_element(task.angles_deg.begin(), task.angles_deg.end()), task.spins_rad_s.size(), task.end,
      o.eps_low, o.eps_high, o.maw_chi, o.first_eps);
  for (const scene::ObliqueModelRun& run : o.runs) s.markdown += model_summary(run, o.plotted);
  s.markdown += fmt::format("\nEvery impact is a row of `{}.csv`.\n\n", task.name);
  return s;
}

}  // namespace restitution::cli
