// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_adhesion.hpp"

#include <fmt/core.h>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "dem/adhesive_check_deck.hpp"
#include "dem/adhesive_lines_lammps.hpp"
#include "dem/adhesive_lines_liggghts.hpp"
#include "dem/dem_codes.hpp"
#include "files/output_files.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

// Writes the check deck when --deck is given; returns the command that runs it (text output names it; the
// JSON output is unchanged).
template <typename Lines>
std::optional<std::string> write_deck(const AdhesiveDemRequest& request, const Lines& r, bool liggghts) {
  if (!request.deck) return std::nullopt;
  const Material& m = request.material;
  if (!m.density_kg_m3 || m.radius1_m != m.radius2_m) {
    throw InvalidInput("--deck with --adhesion needs one --radius and --density (equal spheres)");
  }
  dem::AdhesiveDeckRequest deck;
  deck.liggghts = liggghts;
  deck.lines = r.lines;
  deck.radius_m = m.radius1_m;
  deck.density_kg_per_m3 = *m.density_kg_m3;
  deck.timestep_s = r.timestep_s;
  deck.speeds_m_per_s = r.speeds;
  deck.collisions = r.collisions;
  files::write_file_atomically(*request.deck, dem::adhesive_check_deck(deck));
  const auto code = liggghts ? dem::Code::liggghts : dem::Code::lammps;
  return dem::code_entry(code).check_deck_run + *request.deck;
}

void print_deck_note(const std::optional<std::string>& run) {
  if (run) fmt::print("\ncheck deck written; run it with `{}` (EXPECT and PAIR lines per speed)\n", *run);
}

void print_speed_table(const std::vector<double>& speeds, const std::vector<AdhesiveCollision>& collisions,
                       const char* eps_header) {
  fmt::print("{:>22} {:>10} {:>22} {:>18}\n", "v [m/s]", "outcome", eps_header, "contact [s]");
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const auto& e = collisions[i];
    fmt::print("{:>22.12g} {:>10} {:>22.15g} {:>18.12g}\n", speeds[i], adhesive_outcome_name(e.outcome),
               e.eps, e.contact_time_s);
  }
}

void write_speeds(JsonWriter& json, const std::vector<double>& speeds,
                  const std::vector<AdhesiveCollision>& collisions) {
  json.key("speeds").begin_array();
  for (std::size_t i = 0; i < speeds.size(); ++i) {
    const auto& e = collisions[i];
    json.begin_object();
    json.field("velocity_m_per_s", speeds[i]);
    json.field("outcome", adhesive_outcome_name(e.outcome));
    json.field("eps", e.eps);
    json.field("contact_time_s", e.contact_time_s);
    json.end_object();
  }
  json.end_array();
}

// The members after the adhesion parameter, in the order both codes print them.
void write_contact_and_lines(JsonWriter& json, const AdhesiveContact& c, const char* damping_key,
                             const std::vector<std::string>& lines, double skin_m, double timestep_s) {
  json.field("effective_modulus_pa", c.effective_modulus_pa);
  json.field("effective_radius_m", c.effective_radius_m);
  json.field("effective_mass_kg", c.effective_mass_kg);
  json.field(damping_key, c.damping);
  json.field("lines", lines);
  json.field("skin_m", skin_m);
  json.field("timestep_s", timestep_s);
}

void print_lammps_text(const dem::AdhesiveLammpsLines& r, const AdhesiveContact& c) {
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
  print_speed_table(r.speeds, r.collisions, "eps (LAMMPS rules)");
}

void print_lammps_json(const dem::AdhesiveLammpsLines& r, const AdhesiveContact& c) {
  JsonWriter json;
  json.begin_object();
  json.field("code", "lammps");
  json.field("adhesion", c.model == AdhesiveModel::dmt ? "dmt" : "jkr");
  json.field("surface_energy_j_per_m2", c.surface_energy_j_per_m2);
  write_contact_and_lines(json, c, "lammps_damping_per_m_s", r.lines, r.skin_m, r.timestep_s);
  json.field("break_overlap_m", r.break_overlap_m);
  json.field("sticking_speed_m_per_s", r.sticking.speed_m_per_s);
  if (c.model == AdhesiveModel::jkr_lammps) {
    json.field("textbook_sticking_speed_m_per_s", r.textbook_sticking.speed_m_per_s);
  }
  write_speeds(json, r.speeds, r.collisions);
  fmt::print("{}\n", finish_json_document(json));
}

void print_liggghts_text(const dem::AdhesiveLiggghtsLines& r, const AdhesiveContact& c) {
  fmt::print(
      "# LIGGGHTS 3.8.0 (pair gran): hertz/stiffness with cohesion sjkr, cohesionEnergyDensity = {:g} "
      "J/m^3\n",
      c.cohesion_energy_density_j_per_m3);
  fmt::print("# E* = {:.12g} Pa, R_eff = {:.12g} m, m_eff = {:.12g} kg, gamman = {:.12g} 1/(m s)\n",
             c.effective_modulus_pa, c.effective_radius_m, c.effective_mass_kg, c.damping);
  fmt::print(
      "# the cohesion -k_c * (area of the spheres' intersection circle) acts while they overlap and ends at "
      "overlap 0 with Hertz's force\n");
  for (const auto& line : r.lines) fmt::print("{}\n", line);
  fmt::print("\nsticking speed under LIGGGHTS's rules: {:.12g} m/s ({} solves)\n", r.sticking.speed_m_per_s,
             r.sticking.solves);
  print_speed_table(r.speeds, r.collisions, "eps (LIGGGHTS rules)");
}

void print_liggghts_json(const dem::AdhesiveLiggghtsLines& r, const AdhesiveContact& c) {
  JsonWriter json;
  json.begin_object();
  json.field("code", "liggghts");
  json.field("adhesion", "sjkr");
  json.field("cohesion_energy_density_j_per_m3", c.cohesion_energy_density_j_per_m3);
  write_contact_and_lines(json, c, "liggghts_gamman_per_m_s", r.lines, r.skin_m, r.timestep_s);
  json.field("break_overlap_m", 0.0);
  json.field("sticking_speed_m_per_s", r.sticking.speed_m_per_s);
  write_speeds(json, r.speeds, r.collisions);
  fmt::print("{}\n", finish_json_document(json));
}

int run_liggghts(const AdhesiveDemRequest& request) {
  dem::AdhesiveLiggghtsRequest lines_request;
  lines_request.contact = adhesive_contact_from(AdhesiveModel::sjkr, request.adhesion, request.material,
                                                request.inputs.dissipative_constant_s.value_or(0.0));
  lines_request.speeds = request.inputs.speeds_m_s;
  lines_request.tolerance = request.inputs.tolerance;
  const auto r = dem::adhesive_liggghts_lines(lines_request);
  const auto run = write_deck(request, r, true);
  (request.json ? print_liggghts_json : print_liggghts_text)(r, lines_request.contact);
  if (!request.json) print_deck_note(run);
  return 0;
}

}  // namespace

int run_adhesive_dem(const AdhesiveDemRequest& request) {
  if (*request.adhesion.model == "sjkr") return run_liggghts(request);
  // LAMMPS's `jkr` is our jkr-lammps: its damping and its break rule.
  const AdhesiveModel model =
      *request.adhesion.model == "dmt" ? AdhesiveModel::dmt : AdhesiveModel::jkr_lammps;
  dem::AdhesiveLammpsRequest lines_request;
  lines_request.contact = adhesive_contact_from(model, request.adhesion, request.material,
                                                request.inputs.dissipative_constant_s.value_or(0.0));
  lines_request.young_modulus_pa = request.material.young_modulus_pa;
  lines_request.poisson_ratio = request.material.poisson_ratio;
  lines_request.speeds = request.inputs.speeds_m_s;
  lines_request.tolerance = request.inputs.tolerance;
  const auto r = dem::adhesive_lammps_lines(lines_request);
  const auto run = write_deck(request, r, false);
  (request.json ? print_lammps_json : print_lammps_text)(r, lines_request.contact);
  if (!request.json) print_deck_note(run);
  return 0;
}

}  // namespace restitution::cli
