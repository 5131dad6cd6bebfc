// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_oblique.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "cli/common/parse_errors.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

// The section as the study's inputs for one model, so that the scene and the command take one path.
ObliqueInputs inputs_of(const scene::Scene& scene, const scene::ObliqueTask& task, const std::string& model) {
  const Material& m = scene.materials.at(task.material);
  ObliqueInputs in;
  in.material = m;
  // The material's dissipation (A, or the viscosities' A; the section's reader requires one).
  in.dissipative_constant_s = material_constants(m).dissipative_constant_s;
  in.wall = task.wall;
  in.wall_young_modulus_pa = task.wall_young_modulus_pa;
  in.wall_poisson_ratio = task.wall_poisson_ratio;
  in.fixed_normal = task.fixed_normal;
  in.tangential = model;
  // A k_t per contact radius, in N/m² (the mindlin family, liggghts_history), is mindlin_stiffness; one in
  // N/m tangential_stiffness.
  const TangentialModel* row = find_tangential_model(model);
  const bool per_contact_radius = row != nullptr && row->rule.growth == StiffnessGrowth::contact_radius;
  in.tangential_stiffness = per_contact_radius ? task.mindlin_stiffness : task.tangential_stiffness;
  in.tangential_damping = task.tangential_damping;
  in.friction = task.friction;
  in.end = task.end;
  in.torque_arm = task.torque_arm;
  in.tolerance = task.tolerance;
  in.speed_m_s = task.speed_m_s;
  in.angles_deg = task.angles_deg;
  in.spins_rad_s = task.spins_rad_s;
  return in;
}

// One sentence per model: e_t's range, how many impacts slide, the sticking limit where it was computed (the
// plot's reference: not with plot = false), the impacts that failed.
std::string model_summary(const ObliqueModelRun& run, bool sticking_limit) {
  double lowest = std::numeric_limits<double>::infinity();
  double highest = -std::numeric_limits<double>::infinity();
  std::size_t sliding = 0;
  for (const ObliqueImpact& i : run.impacts) {
    const double e = i.result.tangential_restitution;
    if (std::isfinite(e)) {
      lowest = std::min(lowest, e);
      highest = std::max(highest, e);
    }
    // With damping the contact sticks for its first instants (the damping's part of the cap): "sliding" is
    // sliding for 99 % of the contact.
    if (i.solved() && i.result.slip_time_s >= 0.99 * i.result.contact_time_s) ++sliding;
  }
  std::string limit;
  if (sticking_limit) {
    limit = run.maw.sticking_failure.empty()
                ? fmt::format("; sticking limit e_t(μ → ∞) = {:.6g}", run.maw.sticking_restitution)
                : fmt::format("; sticking limit not computed ({})", one_line(run.maw.sticking_failure));
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
      tangential_name(run.setup.tangential.kind), lowest, highest, sliding, run.impacts.size(), limit,
      failures);
}

}  // namespace

ObliqueSection oblique_section(const scene::Scene& scene, const scene::ObliqueTask& task) {
  ObliqueSection s;
  s.csv = oblique_csv_header_with_model() + "\n";
  const bool plotted = task.plot && task.friction > 0.0;
  try {
    for (const std::string& model : task.models) {
      ObliqueModelRun run;
      run.setup = oblique_setup(inputs_of(scene, task, model), ArgumentStyle::keyword);
      run.impacts = oblique_sweep(run.setup);
      // The sticking limit is the plot's reference: computed only where there is a plot.
      run.maw = plotted ? maw_model(run.setup) : MawModel{run.setup.tangential.kind, std::nan(""), ""};
      s.csv += oblique_csv_rows(run.impacts, tangential_name(run.setup.tangential.kind));
      s.runs.push_back(std::move(run));
    }
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: oblique \"{}\": {}", scene.file_name, task.name, e.what()));
  }
  const ObliqueModelRun& first = s.runs.front();
  const double eps = first_solved_restitution(first.impacts);
  if (plotted && !std::isnan(eps)) {
    std::vector<MawModel> models;
    for (const ObliqueModelRun& run : s.runs) models.push_back(run.maw);
    s.plot_args = maw_plot_arguments(first.setup, eps, models);
  }
  // ε depends on the normal speed v cos θ: its range over the angles, at the section's end; the plot's
  // gross-slip line takes the first solved impact's.
  double eps_low = HUGE_VAL;
  double eps_high = -HUGE_VAL;
  for (const ObliqueImpact& i : first.impacts) {
    if (!i.solved()) continue;
    eps_low = std::min(eps_low, i.result.normal_restitution);
    eps_high = std::max(eps_high, i.result.normal_restitution);
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
      eps_low, eps_high, maw_chi(first.setup), eps);
  for (const ObliqueModelRun& run : s.runs) s.markdown += model_summary(run, plotted);
  s.markdown += fmt::format("\nEvery impact is a row of `{}.csv`.\n\n", task.name);
  return s;
}

}  // namespace restitution::cli
