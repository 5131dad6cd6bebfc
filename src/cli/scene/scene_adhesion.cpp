// SPDX-License-Identifier: BSD-3-Clause
#include "cli/scene/scene_adhesion.hpp"

#include <fmt/core.h>

#include <algorithm>
#include <cmath>

#include "cli/sweep/sweep_adhesion.hpp"

namespace restitution::cli {
namespace {

// The adhesion's strength and the damping, as the section gave them.
std::string contact_words(const scene::AdhesionTask& task, const scene::AdhesionOutcome& o) {
  const AdhesiveContact& c = o.contact;
  const std::string strength =
      c.model == AdhesiveModel::sjkr
          ? fmt::format("cohesion energy density k_c = {:.10g} J/m³", c.cohesion_energy_density_j_per_m3)
          : fmt::format("surface energy γ = {:.10g} J/m² per surface (w = 2γ)", c.surface_energy_j_per_m2);
  const std::string source =
      o.calibration
          ? fmt::format("calibrated to ε = {:.10g} at {:.10g} m/s ({} solves; undamped there: {:.10g})",
                        *task.eps, *task.velocity_m_s, o.calibration->solves, o.calibration->elastic_eps)
          : fmt::format("the dissipative constant of [materials.{}]", task.material);
  const std::string lammps =
      c.model == AdhesiveModel::jkr
          ? ""
          : fmt::format(", i.e. the code's damping coefficient {:.10g} 1/(m s)", c.damping);
  return fmt::format("{}; E* = {:.10g} Pa, R_eff = {:.10g} m, m_eff = {:.10g} kg; A = {:.10g} s{} ({})",
                     strength, c.effective_modulus_pa, c.effective_radius_m, c.effective_mass_kg,
                     o.dissipative_constant_s, lammps, source);
}

// The model in the figure's legend.
const char* model_words(AdhesiveModel model) {
  switch (model) {
    case AdhesiveModel::jkr:
      return "JKR, textbook break";
    case AdhesiveModel::jkr_lammps:
      return "JKR, LAMMPS break (pull-off force)";
    case AdhesiveModel::dmt:
      return "DMT, as LAMMPS codes it";
    case AdhesiveModel::sjkr:
      return "LIGGGHTS sjkr on Hertz";
  }
  return "";
}

std::string sticking_words(const scene::AdhesionOutcome& o) {
  if (o.sticking.speed_m_per_s == 0.0) return "The spheres never stick (sticking speed 0)";
  // The elastic JKR value is the closed form sqrt(2W/m_eff): no solve.
  const std::string how =
      o.sticking.solves == 0 ? "closed form" : fmt::format("{} solves", o.sticking.solves);
  return fmt::format("Sticking speed v_s = {:.10g} m/s ({}): below it the spheres stay bound (ε = 0)",
                     o.sticking.speed_m_per_s, how);
}

// The figure's arguments after the CSV and the image.
std::vector<std::string> plot_arguments(const scene::AdhesionTask& task, const scene::AdhesionOutcome& o) {
  const auto [slowest, fastest] = std::minmax_element(task.speeds_m_s.begin(), task.speeds_m_s.end());
  std::vector<std::string> args = {"--sticking-speed", fmt::format("{:.17g}", o.sticking.speed_m_per_s),
                                   "--model", model_words(task.model)};
  // More than a decade and a bit: a log axis reads better.
  if (*fastest > 20.0 * *slowest) args.insert(args.end(), {"--xscale", "log"});
  return args;
}

void write_summary(JsonWriter& json, const scene::AdhesionTask& task, const scene::AdhesionOutcome& o) {
  json.key("adhesion_" + task.name).begin_object();
  json.field("csv", task.name + ".csv").field("model", adhesive_model_name(task.model));
  json.field("sticking_speed_m_per_s", o.sticking.speed_m_per_s)
      .field("sticking_speed_solves", o.sticking.solves);
  json.field("dissipative_constant_s", o.dissipative_constant_s).field("damping", o.contact.damping);
  json.field("elastic_hysteresis_work_j", o.elastic_hysteresis_work_j)
      .field("break_overlap_m", o.break_overlap_m);
  json.field("speeds", static_cast<long>(o.collisions.size())).field("stuck", static_cast<long>(o.stuck));
  json.field("tolerance", o.tolerance);
  json.end_object();
}

}  // namespace

void write_adhesion_section(const scene::Scene& /*scene*/, const scene::AdhesionTask& task,
                            const scene::AdhesionOutcome& o, SectionOutput& out) {
  std::string csv = adhesive_table_header();
  double low = HUGE_VAL;
  double high = -HUGE_VAL;
  for (std::size_t i = 0; i < o.collisions.size(); ++i) {
    const AdhesiveCollision& c = o.collisions[i];
    csv += adhesive_table_row(task.speeds_m_s[i], c, o.sticking.speed_m_per_s);
    if (c.outcome == AdhesiveOutcome::bounced) {
      low = std::min(low, c.eps);
      high = std::max(high, c.eps);
    }
  }
  out.file(task.name + ".csv", csv);
  out.report(fmt::format("## {}\n\n", task.title));
  out.report(out.plot("scene_adhesion", task.name, plot_arguments(task, o)));
  const auto [slowest, fastest] = std::minmax_element(task.speeds_m_s.begin(), task.speeds_m_s.end());
  const std::string bounced = o.stuck == o.collisions.size()
                                  ? "none bounced"
                                  : fmt::format("ε of those that bounced from {:.10g} to {:.10g}", low, high);
  out.report(fmt::format(
      "Adhesive collisions (docs/adhesion.md) of two spheres of [materials.{}], model `{}`: {}. Undamped, "
      "the "
      "contact breaks at overlap {:.10g} m after the neck took W = {:.10g} J. {}. Of {} impact speeds from "
      "{:.10g} to {:.10g} m/s (tolerance {:g}), {} stuck; {}. Every speed is a row of `{}.csv` (outcome, ε, "
      "1 − ε, contact time, maximal compression, the work to the neck and to viscosity).\n\n",
      task.material, adhesive_model_name(task.model), contact_words(task, o), o.break_overlap_m,
      o.elastic_hysteresis_work_j, sticking_words(o), o.collisions.size(), *slowest, *fastest, o.tolerance,
      o.stuck, bounced, task.name));
  write_summary(out.summary(), task, o);
}

}  // namespace restitution::cli
