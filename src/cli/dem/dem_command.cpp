// SPDX-License-Identifier: BSD-3-Clause
// `restitution dem`: the input lines for a DEM code (LAMMPS, LIGGGHTS, MercuryDPM, YADE, Chrono) that give a
// material the viscoelastic Hertz law, with the ε they give at a few impact speeds (docs/dem.md).
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/parameter_options.hpp"
#include "cli/dem/deck_json.hpp"
#include "cli/dem/dem_adhesion.hpp"
#include "cli/dem/dem_deck.hpp"
#include "cli/dem/dem_oblique.hpp"
#include "cli/dem/dem_polydisperse_output.hpp"
#include "cli/dem/dem_production.hpp"
#include "cli/dem/dem_type_options.hpp"
#include "cli/dem/dem_wall.hpp"
#include "cli/dem/from_fit.hpp"
#include "damping_check/yade_version_lines.hpp"
#include "dem/dem_parameters.hpp"
#include "dem/lines_check.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

// The study's inputs (one option per row of its table, dem/dem_parameters.hpp) and what only the command line
// has: the atom types, --from-fit, --yade-version, --deck, the production, wall, oblique and adhesion
// options.
struct DemOptions {
  dem::DemInputs inputs;
  DemTypeOptions types;      // --radius etc., lists for several atom types
  MaterialOptions material;  // the one pair, from `types`
  bool json = false;
  std::string from_fit;  // fit-data --out FILE: A (and the end) from a fit, with its uncertainty
  bool end_given = false;
  std::string yade_version;  // --yade-version; empty: the yade on PATH
  std::string yade_source;   // how the targeted YADE was chosen (set by target_yade)

  std::optional<std::string> deck;  // --deck FILE: the check deck (cli/dem/dem_deck.hpp)
  std::string deck_run;             // the command that runs it, once written
  ProductionOptions production;     // --timestep, --max-eps-error, --constant-eps
  WallOptions wall;                 // --wall: a sphere on a wall (cli/dem/dem_wall.hpp)
  DemObliqueOptions oblique;        // --angle, --target-et (cli/dem/dem_oblique.hpp)
  AdhesionOptions adhesion;         // --adhesion, --surface-energy (cli/dem/dem_adhesion.hpp)
};

// The YADE the lines are for: --yade-version, else `yade --version` of the one on PATH, else the newest
// lines (2024.02a, the exact law). The second member says which.
dem::YadeVersion target_yade(DemOptions& o) {
  if (!o.yade_version.empty()) {
    o.yade_source = "--yade-version";
    return dem::yade_version_from_name(o.yade_version);
  }
  dem::TargetedYade installed = dem::installed_yade_or_newest();
  o.yade_source = std::move(installed.source);
  return installed.version;
}

// --from-fit: the fit's Hertz β (at --end when given, else the lowest AIC) becomes A for this material.
struct FromFit {
  FitCarryOver fit;
  double k = 0.0;
};
std::optional<FromFit> apply_from_fit(DemOptions& o) {
  if (o.from_fit.empty()) return std::nullopt;
  if (o.inputs.eps || o.inputs.dissipative_constant_s) {
    throw InvalidInput("--from-fit excludes --eps and --dissipative-constant");
  }
  FromFit f;
  f.fit = read_fit_result(
      o.from_fit, o.end_given ? std::optional<CollisionEnd>(end_from_name(o.inputs.end)) : std::nullopt);
  f.k = elastic_constants(material_from(o.material)).k;
  o.inputs.dissipative_constant_s = dissipative_constant_from(f.fit.beta, f.k);
  o.inputs.end = end_name(f.fit.end);
  return f;
}

// Which lines give the law's ε(v) that --from-fit carries over: these, unless the targeted YADE cannot
// express the law (then only the lines of the version that can).
std::string fit_eps_given_by(const dem::LinesResult& r) {
  if (!r.yade_exact_deck) return "the lines above";
  return fmt::format(
      "the YADE 2024.02a lines only, not the lines above (on YADE {} they give the eps printed "
      "after them)",
      r.yade_version->text);
}

std::vector<double> speeds_of(const dem::LinesResult& r) {
  std::vector<double> out;
  for (const auto& e : r.eps) out.push_back(e.velocity_m_s);
  return out;
}

dem::LinesResult compute(DemOptions& o) {
  auto request = dem::request_of<dem::LinesRequest>(o.inputs);
  request.material = material_from(o.material);
  // The targeted YADE first: a bad --yade-version is refused before any solve.
  std::optional<dem::YadeVersion> yade;
  if (!std::string_view(dem::code_entry(request.code).version_query).empty()) yade = target_yade(o);
  dem::LinesResult r = dem::check_lines(request);
  if (yade) damping_check::target_yade_version(r, *yade, o.inputs.tolerance);
  return r;
}

void print_json(const dem::LinesResult& r, const DemOptions& o, const std::optional<FromFit>& from_fit,
                const Production& production, const std::optional<DemOblique>& oblique) {
  JsonWriter json;
  json.begin_object();
  json.field("code", dem::code_name(r.deck.code)).field("end", end_name(r.deck.end));
  json.field("dissipative_constant_s", r.dissipative_constant_s);
  json.field("reference_velocity_m_s", r.reference_velocity_m_s).field("friction", r.friction);
  write_deck_json(json, r.deck);
  write_speed_eps_json(json, r.eps);
  json.key("sizes").begin_array();
  for (const auto& s : r.sizes) {
    json.begin_object().field("radius_factor", s.radius_factor);
    json.field("eps_lines", s.eps_lines).field("eps_law", s.eps_law).end_object();
  }
  json.end_array();
  if (r.yade_version) {
    json.field("yade_version", r.yade_version->text).field("yade_version_source", o.yade_source);
  }
  if (r.yade_exact_deck) {
    // Not these lines: the ones YADE 2024.02a and later take for the exact law, and the ε(v) they give there.
    json.key("yade_exact_law").begin_object().field("needs_yade", "2024.02a");
    json.field("lines", r.yade_exact_deck->lines);
    write_speed_eps_json(json, r.yade_exact_eps);
    json.end_object();
  }
  if (r.yade && !r.yade_exact_deck) {
    json.key("yade_own_conversion").begin_object();
    json.field("en", r.yade->true_eps).field("vn", r.reference_velocity_m_s);
    json.field("dissipative_constant_s", r.yade->dissipative_constant_s);
    json.field("eps_at_vn", r.yade->eps_at_vn).end_object();
  }
  if (from_fit) {
    write_fit_carry_over(json, o.from_fit, from_fit->fit, from_fit->k, speeds_of(r), fit_eps_given_by(r));
  }
  write_production_json(json, r, production, o.production);
  if (oblique) write_oblique_json(json, *oblique);
  if (o.deck) json.key("deck").begin_object().field("file", *o.deck).field("run", o.deck_run).end_object();
  fmt::print("{}\n", finish_json_document(json));
}

void print_text(const dem::LinesResult& r, const DemOptions& o, const std::optional<FromFit>& from_fit,
                const Production& production, const std::optional<DemOblique>& oblique) {
  const char* c = dem::code_entry(r.deck.code).comment;
  fmt::print("{} restitution dem --code {}: viscoelastic Hertz law, A = {:.10g} s, {} end\n", c,
             dem::code_name(r.deck.code), r.dissipative_constant_s, end_name(r.deck.end));
  if (r.yade_version) {
    fmt::print("{} for YADE {} ({}){}\n", c, r.yade_version->text, o.yade_source,
               r.yade_exact_deck
                   ? ": it cannot express this law; the lines below give the eps printed after them"
                   : "");
  }
  for (const auto& p : r.deck.parameters) fmt::print("{} {} = {}: {}\n", c, p.name, p.value, p.meaning);
  for (const auto& n : r.deck.notes) fmt::print("{} {}\n", c, n);
  if (!r.deck.prerequisites.empty()) {
    fmt::print("{} needs before these lines: {} (checked on {})\n", c, fmt::join(r.deck.prerequisites, "; "),
               r.deck.checked_on);
  }
  for (const auto& line : r.deck.lines) fmt::print("{}\n", line);
  fmt::print("{} eps these lines give this pair ({} end):\n", c, end_name(r.deck.end));
  for (const auto& e : r.eps) fmt::print("{}   v = {:<10.6g} m/s  eps = {:.10g}\n", c, e.velocity_m_s, e.eps);
  fmt::print("{} other sizes of this material (radii scaled, same density) at v = {:g} m/s:\n", c,
             r.reference_velocity_m_s);
  for (const auto& s : r.sizes) {
    fmt::print("{}   radii x{:<4g} eps = {:.10g}, the law gives {:.10g}\n", c, s.radius_factor, s.eps_lines,
               s.eps_law);
  }
  if (r.yade_exact_deck) {
    fmt::print("{} on YADE 2024.02a or later these lines give the law itself (not runnable on YADE {}):\n", c,
               r.yade_version->text);
    for (const auto& line : r.yade_exact_deck->lines) fmt::print("{}   {}\n", c, line);
    fmt::print("{} and there give:", c);
    for (const auto& e : r.yade_exact_eps) fmt::print(" eps({:g} m/s) = {:.10f}", e.velocity_m_s, e.eps);
    fmt::print("\n");
  }
  if (r.yade && !r.yade_exact_deck) {
    fmt::print(
        "{} YADE's own conversion of the true (en = {:.10g}, vn = {:g} m/s) gives A = {:.10g} s ({:+.3g} "
        "%),\n",
        c, r.yade->true_eps, r.reference_velocity_m_s, r.yade->dissipative_constant_s,
        100.0 * (r.yade->dissipative_constant_s / r.dissipative_constant_s - 1.0));
    fmt::print("{} which makes eps(vn) = {:.10g}; the en above instead makes YADE recover the exact A\n", c,
               r.yade->eps_at_vn);
  }
  if (from_fit)
    fmt::print("{}", fit_carry_over_text(o.from_fit, from_fit->fit, from_fit->k, speeds_of(r),
                                         fit_eps_given_by(r), c));
  print_production_text(r, production, o.production);
  if (oblique) print_oblique_text(*oblique, c);
  if (o.deck) fmt::print("{} check deck written to {}: run `{}`\n", c, *o.deck, o.deck_run);
}

// --from-fit, --yade-version and the production options are for one pair of spheres; `subject` says what
// takes the damping options only.
void refuse_pair_options(const DemOptions& o, const char* subject) {
  if (!o.from_fit.empty() || !o.yade_version.empty() || any_production_option(o.production)) {
    throw InvalidInput(fmt::format(
        "{} --eps/--velocity or --dissipative-constant, not --from-fit, --yade-version, --timestep, "
        "--max-eps-error or --constant-eps",
        subject));
  }
}

// Several atom types (docs/dem.md, "Polydisperse sets"): lammps and liggghts only.
int run_polydisperse(const DemOptions& o) {
  if (dem::wants_oblique(o.oblique, dem::code_from_name(o.inputs.code), 0.0)) {
    throw InvalidInput("several atom types take no --angle, --target-et or --reference-angle");
  }
  refuse_pair_options(o, "several atom types take");
  auto request = dem::request_of<dem::PolydisperseRequest>(o.inputs);
  set_types(o.types, request);
  if (o.deck) check_deck_size(request.code, request.types.size(), o.inputs.speeds_m_s.size());
  const dem::PolydisperseResult r = dem::polydisperse_lines(request);
  std::optional<WrittenDeck> deck;
  if (o.deck) deck = WrittenDeck{*o.deck, write_check_deck(*o.deck, dem::check_deck_request(r))};
  if (o.json) {
    print_polydisperse_json(r, deck);
  } else {
    print_polydisperse_text(r, deck);
  }
  return 0;
}

// --wall: one sphere on a wall; the options of pairs and type sets are refused by name.
// The adhesive pair's lines: LAMMPS only, one pair, no wall, A given (not calibrated from --eps).
int run_adhesion(const DemOptions& o, const std::vector<std::string>& given) {
  if (!o.adhesion.model) {
    throw InvalidInput("--surface-energy and --cohesion-energy-density belong to --adhesion");
  }
  const bool sjkr = *o.adhesion.model == "sjkr";
  if (sjkr && o.inputs.code != "liggghts") {
    throw InvalidInput(fmt::format(
        "--adhesion sjkr is LIGGGHTS's cohesion model: use --code liggghts (not {})", o.inputs.code));
  }
  if (!sjkr && o.inputs.code != "lammps") {
    throw InvalidInput(fmt::format(
        "--adhesion {} prints LAMMPS's pair granular lines only (not {}'s; LIGGGHTS has --adhesion sjkr)",
        *o.adhesion.model, o.inputs.code));
  }
  if (sjkr && o.wall.wall) throw InvalidInput("--adhesion sjkr is for a pair of spheres, not --wall");
  if (o.wall.wall && *o.adhesion.model == "jkr") {
    throw InvalidInput(
        "--wall with --adhesion jkr: LAMMPS 20220106's fix wall/gran ... jkr uses a pull-off distance of the "
        "wrong dimension and turns the atom into NaN without an error (docs/adhesion.md)");
  }
  for (const auto& option : given) {
    throw InvalidInput(
        fmt::format("{} does not go with --adhesion (give the material, --surface-energy, "
                    "--dissipative-constant and --impact-velocity)",
                    option));
  }
  if (several_types(o.types)) throw InvalidInput("--adhesion is for one pair of spheres, not several types");
  AdhesiveDemRequest request;
  request.adhesion = o.adhesion;
  request.material = material_from(one_pair_material(o.types));
  request.inputs = o.inputs;
  request.json = o.json;
  request.deck = o.deck;
  return run_adhesive_dem(request);
}

int run_wall(const DemOptions& o) {
  if (several_types(o.types) || o.types.radius2 || o.types.mass2) {
    throw InvalidInput("--wall takes one sphere: one --radius, no --radius2, --mass2 or --radius-range");
  }
  refuse_pair_options(o, "--wall takes");
  auto request = dem::request_of<dem::WallRequest>(o.inputs);
  request.sphere = material_from(one_pair_material(o.types));
  request.wall = wall_material(o.wall);
  const bool oblique = dem::wants_oblique(o.oblique, request.code, o.inputs.friction);
  dem::WallResult r = dem::wall_lines(request);
  dem::apply_tangential_choice(r.deck, o.oblique, o.inputs.friction);
  std::optional<DemOblique> impacts;
  if (oblique) {
    impacts = dem::wall_oblique(r.deck, r.contact, o.oblique, r.reference_velocity_m_s, o.inputs.tolerance);
    warn_oblique(*impacts);
  }
  print_wall(r, o.json, o.deck, impacts);
  return 0;
}

}  // namespace

void add_dem_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<DemOptions>();
  CLI::App* cmd = app.add_subcommand(
      "dem", "input lines giving a DEM code (" + dem::code_list(", ") + ") this law, and its eps");
  add_parameter_options(*cmd, dem::dem_fields(), o->inputs, [&](const dem::DemField& f, CLI::Option* option) {
    if (f.word == &dem::DemInputs::code) {
      option->required();
      add_dem_type_options(*cmd, o->types);
    }
    if (f.optional_number == &dem::DemInputs::dissipative_constant_s) {
      cmd->add_option(
          "--from-fit", o->from_fit,
          "instead of --eps or --dissipative-constant: the JSON of fit-data --out; A from its Hertz fit "
          "(at --end if given, else the lowest AIC) with the uncertainty it carries over (none when the fit "
          "itself rejects it, said so)");
    }
    if (f.numbers == &dem::DemInputs::speeds_m_s) add_deprecated_alias(*cmd, option, "--speeds");
  });
  cmd->add_option("--yade-version", o->yade_version,
                  "YADE version the yade lines are for, e.g. 2023.02a (no vn: a constant eps) or 2024.02a "
                  "(default: yade --version on PATH)");
  cmd->add_option(
      "--deck", o->deck,
      fmt::format("also write FILE, a complete input for {} that collides "
                  "the pair at the speeds and prints the eps it measures next to restitution's "
                  "(docs/dem.md); at most {} collisions (type pairs x speeds: {} types at 1 speed, "
                  "{} at the default 3) and {:.3g} sphere-steps (spheres x steps: radii or speeds far "
                  "apart need many steps), yade {} speeds",
                  dem::code_list(" or ", [](const dem::CodeEntry& e) { return e.check_deck != nullptr; }),
                  dem::kMaxDeckCollisionsLammps, dem::max_deck_types(dem::kMaxDeckCollisionsLammps, 1),
                  dem::max_deck_types(dem::kMaxDeckCollisionsLammps, 3), dem::kMaxDeckSphereSteps,
                  dem::kMaxDeckCollisionsYade));
  add_production_options(*cmd, o->production);
  add_wall_options(
      *cmd, o->wall,
      "a sphere (--radius, --density or --mass) hitting a flat wall: the code's wall lines, in its "
      "wall convention (lammps: fix wall/gran granular)");
  add_dem_oblique_options(*cmd, o->oblique);
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  add_adhesion_options(*cmd, o->adhesion, {"jkr", "dmt", "sjkr"});
  cmd->callback([o, cmd, &chosen] {
    o->end_given = cmd->count("--end") > 0;
    if (o->adhesion.any()) {
      std::vector<std::string> given;  // what the adhesive lines do not take
      for (const char* option : {"--eps", "--from-fit", "--end", "--angle", "--target-et", "--tangential",
                                 "--friction", "--timestep", "--constant-eps", "--yade-version", "--wall"}) {
        if (cmd->count(option) > 0 &&
            !(std::string_view(option) == "--wall" && o->adhesion.model && *o->adhesion.model == "jkr")) {
          given.emplace_back(option);
        }
      }
      chosen = [o, given] { return run_adhesion(*o, given); };
      return;
    }
    chosen = [o] {
      if (o->wall.wall || o->wall.young_modulus || o->wall.poisson_ratio) {
        if (o->deck) check_deck_target(*o->deck, dem::code_from_name(o->inputs.code));
        return run_wall(*o);
      }
      if (o->deck) check_deck_target(*o->deck, dem::code_from_name(o->inputs.code));
      if (several_types(o->types)) {
        if (dem::tangential_chosen(o->oblique)) {
          throw InvalidInput("--tangential is for one pair of spheres or a wall, not several types");
        }
        return run_polydisperse(*o);
      }
      if (o->deck) check_deck_size(dem::code_from_name(o->inputs.code), 1, o->inputs.speeds_m_s.size());
      o->material = one_pair_material(o->types);
      const bool oblique =
          dem::wants_oblique(o->oblique, dem::code_from_name(o->inputs.code), o->inputs.friction);
      const std::optional<FromFit> from_fit = apply_from_fit(*o);
      dem::LinesResult r = compute(*o);
      dem::apply_tangential_choice(r.deck, o->oblique, o->inputs.friction);
      const Production p = production(r, material_from(o->material), o->production, o->inputs.tolerance);
      std::optional<DemOblique> impacts;
      if (oblique) {
        impacts = dem::pair_oblique(r.deck, dem::pair_of(material_from(o->material)), o->oblique,
                                    r.reference_velocity_m_s, o->inputs.tolerance);
        if (impacts) warn_oblique(*impacts);
      }
      if (o->deck) o->deck_run = write_check_deck(*o->deck, r, material_from(o->material), impacts);
      if (o->json) {
        print_json(r, *o, from_fit, p, impacts);
      } else {
        print_text(r, *o, from_fit, p, impacts);
      }
      return 0;
    };
  });
}

}  // namespace restitution::cli
