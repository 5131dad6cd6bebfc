// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_adhesion.hpp"

#include <fmt/core.h>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "dem/adhesive_lines_lammps.hpp"

namespace restitution::cli {
namespace {

void print_text(const dem::AdhesiveLammpsLines& r, const AdhesiveContact& c) {
  fmt::print(
      "# LAMMPS 20220106 (pair granular): {} with damping viscoelastic, gamma = {:g} J/m^2 per surface\n",
      c.model == AdhesiveModel::dmt ? "dmt" : "jkr", c.surface_energy_j_per_m2);
  fmt::print("# E* = {:.12g} Pa, R_eff = {:.12g} m, m_eff = {:.12g} kg, damp = {:.12g} 1/(m s)\n",
             c.effective_modulus_pa, c.effective_radius_m, c.effective_mass_kg, c.damping);
  fmt::print(
      "# the contact breaks at overlap {:.12g} m; skin >= 2 |pull-off| (jkr); the time step keeps |eps "
      "error| <= 1e-5 at every listed bounce\n",
      r.break_overlap_m);
  for (const auto& line : r.lines) fmt::print("{}\n", line);
  fmt::print("\nsticking speed under LAMMPS's rules: {:.12g} m/s ({} solves)\n", r.sticking.speed_m_per_s,
             r.sticking.solves);
  if (c.model == AdhesiveModel::jkr_lammps) {
    fmt::print("textbook JKR (break where d(overlap)/da = 0, damping A dF/d(overlap), same A): {:.12g} m/s\n",
               r.textbook_sticking.speed_m_per_s);
  }
  fmt::print("{:>22} {:>10} {:>22} {:>18}\n", "v [m/s]", "outcome", "eps (LAMMPS rules)", "contact [s]");
  for (std::size_t i = 0; i < r.speeds.size(); ++i) {
    const auto& e = r.collisions[i];
    fmt::print("{:>22.12g} {:>10} {:>22.15g} {:>18.12g}\n", r.speeds[i], adhesive_outcome_name(e.outcome),
               e.eps, e.contact_time_s);
  }
}

void print_json(const dem::AdhesiveLammpsLines& r, const AdhesiveContact& c) {
  JsonWriter json;
  json.begin_object();
  json.field("code", "lammps");
  json.field("adhesion", c.model == AdhesiveModel::dmt ? "dmt" : "jkr");
  json.field("surface_energy_j_per_m2", c.surface_energy_j_per_m2);
  json.field("effective_modulus_pa", c.effective_modulus_pa);
  json.field("effective_radius_m", c.effective_radius_m);
  json.field("effective_mass_kg", c.effective_mass_kg);
  json.field("lammps_damping_per_m_s", c.damping);
  json.key("lines").begin_array();
  for (const auto& line : r.lines) json.value(line);
  json.end_array();
  json.field("skin_m", r.skin_m);
  json.field("timestep_s", r.timestep_s);
  json.field("break_overlap_m", r.break_overlap_m);
  json.field("sticking_speed_m_per_s", r.sticking.speed_m_per_s);
  if (c.model == AdhesiveModel::jkr_lammps) {
    json.field("textbook_sticking_speed_m_per_s", r.textbook_sticking.speed_m_per_s);
  }
  json.key("speeds").begin_array();
  for (std::size_t i = 0; i < r.speeds.size(); ++i) {
    const auto& e = r.collisions[i];
    json.begin_object();
    json.field("velocity_m_per_s", r.speeds[i]);
    json.field("outcome", adhesive_outcome_name(e.outcome));
    json.field("eps", e.eps);
    json.field("contact_time_s", e.contact_time_s);
    json.end_object();
  }
  json.end_array();
  fmt::print("{}\n", finish_json_document(json));
}

}  // namespace

int run_adhesive_dem(const AdhesiveDemRequest& request) {
  // LAMMPS's `jkr` is our jkr-lammps: its damping and its break rule.
  const AdhesiveModel model =
      *request.adhesion.model == "dmt" ? AdhesiveModel::dmt : AdhesiveModel::jkr_lammps;
  dem::AdhesiveLammpsRequest lines_request;
  lines_request.contact =
      adhesive_contact_from(model, request.adhesion, request.material, request.dissipative_constant_s);
  lines_request.young_modulus_pa = request.material.young_modulus_pa;
  lines_request.poisson_ratio = request.material.poisson_ratio;
  lines_request.speeds = request.speeds;
  lines_request.tolerance = request.tolerance;
  const auto r = dem::adhesive_lammps_lines(lines_request);
  if (request.json) {
    print_json(r, lines_request.contact);
  } else {
    print_text(r, lines_request.contact);
  }
  return 0;
}

}  // namespace restitution::cli
