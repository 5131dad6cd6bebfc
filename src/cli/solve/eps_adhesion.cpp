// SPDX-License-Identifier: BSD-3-Clause
#include "cli/solve/eps_adhesion.hpp"

#include <fmt/core.h>

#include <vector>

#include "adhesion/adhesive_study.hpp"
#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"

namespace restitution::cli {
namespace {

struct AdhesiveReport {
  AdhesiveContact contact;
  double tolerance = 0.0;
  std::optional<double> velocity;
  AdhesiveStudy study;  // one collision with the velocity
};

const char* damping_unit(AdhesiveModel model) {
  if (model == AdhesiveModel::jkr) return "s (A)";
  return model == AdhesiveModel::sjkr ? "1/(m s) (LIGGGHTS gamman)" : "1/(m s) (LAMMPS damp)";
}

const char* damping_key(AdhesiveModel model) {
  if (model == AdhesiveModel::jkr) return "dissipative_constant_s";
  return model == AdhesiveModel::sjkr ? "liggghts_gamman_per_m_s" : "lammps_damping_per_m_s";
}

void print_table(const AdhesiveReport& r) {
  const auto& c = r.contact;
  if (c.model == AdhesiveModel::sjkr) {
    fmt::print("sjkr adhesive collision (LIGGGHTS), cohesion energy density {:g} J/m^3, tolerance {:g}\n",
               c.cohesion_energy_density_j_per_m3, r.tolerance);
  } else {
    fmt::print("{} adhesive collision, surface energy {:g} J/m^2 per surface (w = 2 gamma), tolerance {:g}\n",
               adhesive_model_name(c.model), c.surface_energy_j_per_m2, r.tolerance);
  }
  fmt::print("  E* = {:.12g} Pa   R_eff = {:.12g} m   m_eff = {:.12g} kg   damping = {:.12g} {}\n",
             c.effective_modulus_pa, c.effective_radius_m, c.effective_mass_kg, c.damping,
             damping_unit(c.model));
  fmt::print("  break overlap {:.12g} m   elastic hysteresis work {:.12g} J\n", r.study.break_overlap_m,
             r.study.elastic_hysteresis_work_j);
  fmt::print("  sticking speed v_s = {:.12g} m/s ({} solves)\n", r.study.sticking.speed_m_per_s,
             r.study.sticking.solves);
  if (!r.velocity) return;
  const auto& e = r.study.collisions.front();
  fmt::print("  at v = {:.12g} m/s: {}   eps = {:.15g}   1 - eps = {:.15g}\n", *r.velocity,
             adhesive_outcome_name(e.outcome), e.eps, e.one_minus_eps);
  fmt::print("  contact time {:.12g} s   maximal compression {:.12g} m\n", e.contact_time_s,
             e.max_compression_m);
  fmt::print(
      "  work to the neck (hysteresis) {:.12g} J   to viscosity {:.12g} J   (1/2) m_eff v^2 / adhesion "
      "energy unit = {:.12g}\n",
      e.hysteresis_work_j, e.viscous_work_j, e.kinetic_to_adhesion_energy);
  fmt::print("  solver: {} steps, {} right-hand sides, {} root functions\n", e.stats.steps,
             e.stats.rhs_evaluations, e.stats.root_evaluations);
}

void print_json(const AdhesiveReport& r) {
  const auto& c = r.contact;
  JsonWriter json;
  json.begin_object();
  json.field("adhesion", adhesive_model_name(c.model).c_str());
  if (c.model == AdhesiveModel::sjkr) {
    json.field("cohesion_energy_density_j_per_m3", c.cohesion_energy_density_j_per_m3);
  } else {
    json.field("surface_energy_j_per_m2", c.surface_energy_j_per_m2);
  }
  json.field("effective_modulus_pa", c.effective_modulus_pa);
  json.field("effective_radius_m", c.effective_radius_m);
  json.field("effective_mass_kg", c.effective_mass_kg);
  json.field(damping_key(c.model), c.damping);
  json.field("tolerance", r.tolerance);
  json.field("break_overlap_m", r.study.break_overlap_m);
  json.field("elastic_hysteresis_work_j", r.study.elastic_hysteresis_work_j);
  json.field("sticking_speed_m_per_s", r.study.sticking.speed_m_per_s);
  json.field("sticking_speed_solves", r.study.sticking.solves);
  if (r.velocity) {
    const auto& e = r.study.collisions.front();
    json.field("velocity_m_per_s", *r.velocity);
    json.field("outcome", adhesive_outcome_name(e.outcome));
    json.field("eps", e.eps);
    json.field("one_minus_eps", e.one_minus_eps);
    json.field("contact_time_s", e.contact_time_s);
    json.field("max_compression_m", e.max_compression_m);
    json.field("hysteresis_work_j", e.hysteresis_work_j);
    json.field("viscous_work_j", e.viscous_work_j);
    json.field("kinetic_to_adhesion_energy", e.kinetic_to_adhesion_energy);
  }
  fmt::print("{}\n", finish_json_document(json));
}

}  // namespace

int run_adhesive_eps(const AdhesiveContact& contact, std::optional<double> velocity_m_per_s, double tolerance,
                     bool json) {
  std::vector<double> speeds;
  if (velocity_m_per_s) speeds.push_back(*velocity_m_per_s);
  const AdhesiveReport report{contact, tolerance, velocity_m_per_s,
                              study_adhesive_contact(contact, speeds, tolerance)};
  if (json) {
    print_json(report);
  } else {
    print_table(report);
  }
  return 0;
}

}  // namespace restitution::cli
