// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_polydisperse_output.hpp"

#include <fmt/core.h>

#include "cli/common/build_json.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/dem/deck_json.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {

void print_polydisperse_text(const dem::PolydisperseResult& r, const std::optional<WrittenDeck>& deck) {
  fmt::print("# restitution dem --code {}: viscoelastic Hertz law, A = {:.10g} s, {} end, {} atom types\n",
             dem::code_name(r.code), r.dissipative_constant_s, end_name(r.end), r.types.size());
  for (std::size_t i = 0; i < r.types.size(); ++i) {
    const dem::ParticleType& t = r.types[i];
    fmt::print(
        "# type {}: radius {} m (diameter {} m), density {} kg/m^3, mass {:.6g} kg, material {} (Y = {} Pa, "
        "nu = {})\n",
        i + 1, t.radius_m, 2.0 * t.radius_m, t.density_kg_m3, sphere_mass_kg(t.radius_m, t.density_kg_m3),
        t.material, t.young_modulus_pa, t.poisson_ratio);
  }
  for (const auto& n : r.notes) fmt::print("# {}\n", n);
  for (const auto& line : r.lines) fmt::print("{}\n", line);
  fmt::print("# eps these lines give each type pair ({} end):\n", end_name(r.end));
  for (const auto& p : r.pairs) {
    fmt::print("#   pair ({},{}): E* = {:.6g} Pa, R_eff = {:.6g} m, m_eff = {:.6g} kg:", p.type1, p.type2,
               p.pair.effective_modulus_pa, p.pair.effective_radius_m, p.pair.effective_mass_kg);
    for (const auto& e : p.eps) fmt::print(" eps({:g} m/s) = {:.10g}", e.velocity_m_s, e.eps);
    fmt::print("\n");
  }
  if (r.binning) {
    const dem::BinningError& b = *r.binning;
    fmt::print("# binning: {} log-spaced classes over [{:g}, {:g}] m, edges", r.types.size(),
               b.edges_m.front(), b.edges_m.back());
    for (double e : b.edges_m) fmt::print(" {:.6g}", e);
    fmt::print(" m; each type is its class's log-midpoint\n");
    fmt::print(
        "# worst eps error of the binning (spheres of any radii in the range with their classes' lines, "
        "{} radii per class, edges included, at the speeds above): |eps - eps_law| <= {:.3g}, relative to "
        "min(eps, 1 - eps) {:.3g}, at radii {:.6g} m and {:.6g} m, v = {:g} m/s (eps {:.10g}, the law "
        "{:.10g})\n",
        b.grid_points_per_class, b.worst_abs_error, b.worst_relative_error, b.radius1_m, b.radius2_m,
        b.velocity_m_s, b.eps_code, b.eps_law);
  }
  if (deck) fmt::print("# check deck written to {}: run `{}`\n", deck->file, deck->run);
}

void print_polydisperse_json(const dem::PolydisperseResult& r, const std::optional<WrittenDeck>& deck) {
  JsonWriter json;
  json.begin_object();
  json.field("code", dem::code_name(r.code)).field("end", end_name(r.end));
  json.field("dissipative_constant_s", r.dissipative_constant_s);
  json.field("dissipative_constant_source", r.calibrated ? "calibrated for type pair (1,1)" : "given");
  json.field("reference_velocity_m_s", r.reference_velocity_m_s).field("friction", r.friction);
  json.key("types").begin_array();
  for (std::size_t i = 0; i < r.types.size(); ++i) {
    const dem::ParticleType& t = r.types[i];
    json.begin_object().field("type", static_cast<int>(i + 1)).field("radius_m", t.radius_m);
    json.field("density_kg_m3", t.density_kg_m3)
        .field("mass_kg", sphere_mass_kg(t.radius_m, t.density_kg_m3));
    json.field("material", t.material).field("young_modulus_pa", t.young_modulus_pa);
    json.field("poisson_ratio", t.poisson_ratio).end_object();
  }
  json.end_array();
  json.key("pairs").begin_array();
  for (const auto& p : r.pairs) {
    json.begin_object().field("type1", p.type1).field("type2", p.type2);
    json.field("effective_modulus_pa", p.pair.effective_modulus_pa);
    json.field("effective_radius_m", p.pair.effective_radius_m);
    json.field("effective_mass_kg", p.pair.effective_mass_kg).field("beta", p.beta);
    json.key("parameters").begin_object();
    for (const auto& q : p.deck.parameters) json.field(q.name, q.value);
    json.end_object();
    write_speed_eps_json(json, p.eps);
    json.end_object();
  }
  json.end_array();
  json.key("meanings").begin_object();
  for (const auto& q : r.pairs.front().deck.parameters) json.field(q.name, q.meaning);
  json.end_object();
  json.field("lines", r.lines);
  json.field("notes", r.notes);
  if (r.binning) {
    const dem::BinningError& b = *r.binning;
    json.key("binning").begin_object().field("spacing", "log");
    json.field("edges_m", b.edges_m);
    json.field("grid_points_per_class", b.grid_points_per_class);
    json.field("worst_abs_error", b.worst_abs_error).field("worst_relative_error", b.worst_relative_error);
    json.field("radius1_m", b.radius1_m).field("radius2_m", b.radius2_m);
    json.field("velocity_m_s", b.velocity_m_s).field("eps_lines", b.eps_code).field("eps_law", b.eps_law);
    json.end_object();
  }
  if (deck) json.key("deck").begin_object().field("file", deck->file).field("run", deck->run).end_object();
  fmt::print("{}\n", finish_json_document(json));
}

}  // namespace restitution::cli
