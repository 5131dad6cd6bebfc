// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_wall.hpp"

#include <fmt/core.h>
#include <fmt/ranges.h>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/dem/deck_json.hpp"
#include "dem/check_deck.hpp"
#include "dem/oblique_check_deck.hpp"
#include "files/output_files.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

std::string wall_words(const dem::WallResult& r) {
  return r.rigid_wall ? "rigid wall" : "wall of its own material";
}

void print_json(const dem::WallResult& r, const std::optional<std::string>& deck, const std::string& run,
                const std::optional<DemOblique>& oblique) {
  JsonWriter json;
  json.begin_object();
  json.field("code", dem::code_name(r.deck.code)).field("end", end_name(r.deck.end));
  json.field("contact", "sphere-wall").field("rigid_wall", r.rigid_wall);
  json.field("wall_convention", dem::code_entry(r.deck.code).wall);
  json.field("effective_modulus_pa", r.contact.effective_modulus_pa);
  json.field("effective_radius_m", r.contact.effective_radius_m);
  json.field("effective_mass_kg", r.contact.effective_mass_kg);
  json.field("dissipative_constant_s", r.dissipative_constant_s);
  json.field("reference_velocity_m_s", r.reference_velocity_m_s).field("friction", r.friction);
  write_deck_json(json, r.deck);
  write_speed_eps_json(json, r.eps);
  if (oblique) write_oblique_json(json, *oblique);
  if (deck) json.key("deck").begin_object().field("file", *deck).field("run", run).end_object();
  fmt::print("{}\n", finish_json_document(json));
}

void print_text(const dem::WallResult& r, const std::optional<std::string>& deck, const std::string& run,
                const std::optional<DemOblique>& oblique) {
  const char* c = dem::code_entry(r.deck.code).comment;
  fmt::print(
      "{} restitution dem --code {} --wall: a sphere on a {}, viscoelastic Hertz law, A = {:.10g} s, {} "
      "end\n",
      c, dem::code_name(r.deck.code), wall_words(r), r.dissipative_constant_s, end_name(r.deck.end));
  fmt::print("{} contact: E* = {:.10g} Pa, R* = R = {:.10g} m, m_eff = m = {:.10g} kg\n", c,
             r.contact.effective_modulus_pa, r.contact.effective_radius_m, r.contact.effective_mass_kg);
  fmt::print("{} convention: {}\n", c, dem::code_entry(r.deck.code).wall);
  for (const auto& p : r.deck.parameters) fmt::print("{} {} = {}: {}\n", c, p.name, p.value, p.meaning);
  for (const auto& n : r.deck.notes) fmt::print("{} {}\n", c, n);
  fmt::print("{} needs before these lines: {} (checked on {})\n", c, fmt::join(r.deck.prerequisites, "; "),
             r.deck.checked_on);
  for (const auto& line : r.deck.lines) fmt::print("{}\n", line);
  fmt::print("{} eps these lines give this sphere on the wall ({} end):\n", c, end_name(r.deck.end));
  for (const auto& e : r.eps) fmt::print("{}   v = {:<10.6g} m/s  eps = {:.10g}\n", c, e.velocity_m_s, e.eps);
  if (oblique) print_oblique_text(*oblique, c);
  if (deck) fmt::print("{} wall check deck written to {}: run `{}`\n", c, *deck, run);
}

}  // namespace

void add_wall_options(CLI::App& command, WallOptions& o, const std::string& wall_help) {
  command.add_flag("--wall", o.wall, wall_help);
  command.add_option("--wall-young-modulus", o.young_modulus,
                     "with --wall: the wall's Young's modulus in Pa (default: a rigid wall)");
  command.add_option("--wall-poisson-ratio", o.poisson_ratio,
                     "with --wall: the wall's Poisson ratio (with --wall-young-modulus)");
}

std::optional<dem::WallMaterial> wall_material(const WallOptions& o) {
  if (!o.wall && (o.young_modulus || o.poisson_ratio)) {
    throw InvalidInput("--wall-young-modulus and --wall-poisson-ratio need --wall");
  }
  if (o.young_modulus.has_value() != o.poisson_ratio.has_value()) {
    throw InvalidInput("give both --wall-young-modulus and --wall-poisson-ratio, or neither (a rigid wall)");
  }
  if (!o.young_modulus) return std::nullopt;
  return dem::WallMaterial{*o.young_modulus, *o.poisson_ratio};
}

void print_wall(const dem::WallResult& r, bool json, const std::optional<std::string>& deck,
                const std::optional<DemOblique>& oblique) {
  std::string run;
  if (deck) {
    std::string text = dem::wall_check_deck(r);
    if (oblique) text += dem::oblique_check_section(*oblique, r.deck.prerequisites, r.deck.lines);
    files::write_file_atomically(*deck, text);
    run = dem::check_deck_command(r.deck.code, *deck);
  }
  if (json) {
    print_json(r, deck, run, oblique);
  } else {
    print_text(r, deck, run, oblique);
  }
}

}  // namespace restitution::cli
