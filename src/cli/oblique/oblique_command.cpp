// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique`: oblique impacts of two spheres of one material, or of a sphere on a wall, with a
// LAMMPS `pair granular` tangential model: the tangential restitution, rebound angle, spin, impulse ratio and
// the stick/slip history per impact angle (src/oblique/, docs/oblique.md).
#include <fmt/core.h>
#include <fmt/ranges.h>

#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/options.hpp"
#include "cli/common/parameter_options.hpp"
#include "cli/common/parse_errors.hpp"
#include "cli/common/plot_script.hpp"
#include "cli/oblique/oblique_sweep.hpp"
#include "files/output_files.hpp"
#include "files/output_guards.hpp"
#include "files/scratch_file.hpp"
#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/solve_types.hpp"
#include "restitution/units.hpp"
#include "restitution_oblique/oblique_parameters.hpp"
#include "restitution_oblique/oblique_study.hpp"
#include "scene/figure_formats.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

// The study's inputs (one option per row of its table, restitution_oblique/oblique_parameters.hpp) and what
// only the command line has: the shared material options, --angle-range and the outputs.
struct ObliqueCommandOptions {
  ObliqueInputs inputs;
  MaterialOptions material;
  std::string angle_range;  // FROM:TO:N, instead of --angle
  bool json = false;
  std::string out;
  std::string plot;    // Maw's diagram
  std::string format;  // figure formats besides the one --plot's extension names
};

using Setup = ObliqueSetup;

// The options as the study's inputs; its rules (src/oblique/oblique_study.cpp) check them.
Setup setup_of(const ObliqueCommandOptions& o) {
  if (o.inputs.wall && (o.material.radius2 || o.material.mass2)) {
    throw InvalidInput("--wall takes one sphere: drop --radius2 and --mass2");
  }
  if (!o.angle_range.empty() && !o.inputs.angles_deg.empty()) {
    throw InvalidInput("give --angle or --angle-range, not both");
  }
  ObliqueInputs in = o.inputs;
  in.material = material_from(o.material);
  if (!o.angle_range.empty()) in.angles_deg = angle_range(o.angle_range);
  return oblique_setup(in, ArgumentStyle::option);
}

void print_json(const ObliqueCommandOptions& o, const Setup& s, const std::vector<ObliqueImpact>& impacts) {
  JsonWriter json;
  json.begin_object().field("tangential_model", tangential_name(s.tangential.kind));
  json.field("contact", o.inputs.wall ? "sphere-wall" : "sphere-sphere").field("end", o.inputs.end);
  if (o.inputs.wall) {
    json.field("rigid_wall", s.rigid_wall);
    if (!s.rigid_wall) {
      json.field("wall_young_modulus_pa", *o.inputs.wall_young_modulus_pa)
          .field("wall_poisson_ratio", *o.inputs.wall_poisson_ratio);
    }
  }
  json.field("effective_modulus_pa", s.effective_modulus_pa)
      .field("effective_shear_modulus_pa", s.effective_shear_modulus_pa);
  json.field("law", law_name(s.normal.kind)).field("dissipative_constant_s", s.dissipative_constant_s);
  if (o.inputs.eps)
    json.field("calibrated_eps", *o.inputs.eps).field("calibration_velocity_m_s", *o.inputs.eps_velocity_m_s);
  json.field("torque_arm", o.inputs.torque_arm).field("fixed_normal", o.inputs.wall || o.inputs.fixed_normal);
  json.field("normal_stiffness_N_m1_5", s.normal.stiffness)
      .field("normal_damping_N_s_m1_5", s.normal.damping);
  json.field("tangential_stiffness", s.tangential.stiffness);
  json.field("tangential_damping_factor", s.tangential.damping_factor)
      .field("friction", s.tangential.friction);
  json.field("speed_m_s", o.inputs.speed_m_s).field("tolerance", o.inputs.tolerance);
  json.field("maw_chi", maw_chi(s));
  if (!o.out.empty()) json.field("csv", o.out);
  if (!o.plot.empty()) json.field("plot", o.plot);
  json.key("impacts").begin_array();
  for (const ObliqueImpact& impact : impacts) {
    const ObliqueResult& r = impact.result;
    json.begin_object().field("angle_deg", impact.angle_deg);
    json.field("initial_spin_rad_s", impact.initial_spin_rad_s);
    json.field("status", impact.solved() ? "solved" : "failed");
    if (!impact.solved()) json.field("failure", impact.failure);
    json.field("normal_restitution", r.normal_restitution);
    json.key("tangential_restitution");
    if (std::isfinite(r.tangential_restitution)) {
      json.value(r.tangential_restitution);
    } else {
      json.null();  // no slip at impact: e_t is undefined
    }
    json.field("rebound_angle_deg", r.rebound_angle_rad / kRadiansPerDegree);
    json.field("spin_rad_s", r.spin_first_rad_s);
    if (!o.inputs.wall) json.field("spin2_rad_s", r.spin_second_rad_s);
    json.field("impulse_ratio", r.impulse_ratio).field("contact_time_s", r.contact_time_s);
    if (!o.inputs.wall)
      json.field("line_of_centres_turn_deg", r.line_of_centres_turn_rad / kRadiansPerDegree);
    json.field("stick_time_s", r.stick_time_s).field("slip_time_s", r.slip_time_s);
    json.key("modes").begin_array();
    for (const ModeSwitch& m : r.switches) {
      json.begin_object().field("time_s", m.time_s).field("mode", mode_name(m.mode)).end_object();
    }
    json.end_array();
    json.field("steps", r.stats.steps).field("relative_tolerance", impact.relative_tolerance);
    json.field("conditioning", impact.conditioning);
    // Maw's ψ: null without friction, where it is undefined.
    for (const auto& [key, psi] :
         {std::pair{"psi_in", impact.psi_in}, std::pair{"psi_out", impact.psi_out}}) {
      json.key(key);
      if (std::isfinite(psi)) {
        json.value(psi);
      } else {
        json.null();
      }
    }
    json.end_object();
  }
  json.end_array();
  fmt::print("{}\n", finish_json_document(json));
}

// Which contact, in words: the wall is rigid unless it has a material (as `dem --wall`).
std::string contact_words(const ObliqueCommandOptions& o, const Setup& s) {
  if (!o.inputs.wall) return "two spheres of one material";
  if (s.rigid_wall) return "a sphere on a rigid wall";
  return fmt::format("a sphere on a wall of Y = {:g} Pa, nu = {:g}", *o.inputs.wall_young_modulus_pa,
                     *o.inputs.wall_poisson_ratio);
}

std::string damping_words(const ObliqueCommandOptions& o, const Setup& s) {
  if (o.inputs.eps) {
    const std::string what = s.normal.kind == LawKind::viscoelastic_hertz
                                 ? fmt::format("A = {:.10g} s", s.dissipative_constant_s)
                                 : std::string("gamma");
    return fmt::format("{} calibrated: eps = {:g} head-on at {:g} m/s", what, *o.inputs.eps,
                       *o.inputs.eps_velocity_m_s);
  }
  return fmt::format("A = {:.10g} s{}", s.dissipative_constant_s,
                     s.dissipative_constant_s == 0.0 ? " (elastic)" : "");
}

std::string tangential_words(const Setup& s) {
  if (s.tangential.friction == 0.0) {
    return fmt::format("frictionless (friction 0): no tangential force, u and the spins unchanged");
  }
  const TangentialModel& model = tangential_model(s.tangential.kind);
  std::string stiffness;
  if (model.has_stiffness()) {
    stiffness =
        fmt::format("k_t = {:.10g} {}{}, ", s.tangential.stiffness, model.stiffness_unit,
                    model.rule.growth == StiffnessGrowth::contact_radius ? " (times sqrt(R* delta))" : "");
  }
  return fmt::format("{} ({} {}): {}damping {:.6g}, friction {:.6g}", model.name, model.code_title,
                     model.source, stiffness, s.tangential.damping_factor, s.tangential.friction);
}

void print_text(const ObliqueCommandOptions& o, const Setup& s, const std::vector<ObliqueImpact>& impacts) {
  const bool pair = !o.inputs.wall;
  fmt::print(
      "# oblique impact, {}: E* = {:.10g} Pa; {} k = {:.10g} N/m^1.5, gamma = {:.10g} N s/m^(1+b), {}; "
      "eps_n at the {} end\n",
      contact_words(o, s), s.effective_modulus_pa, law_name(s.normal.kind), s.normal.stiffness,
      s.normal.damping, damping_words(o, s), o.inputs.end);
  fmt::print("# tangential {}; speed {:g} m/s\n", tangential_words(s), o.inputs.speed_m_s);
  fmt::print("{:>9} {:>11} {:>14} {:>14} {:>12} {:>14} {}{:>12} {:>12} {:>10} {:>10}  modes\n", "angle_deg",
             "spin0_rad_s", "eps_n", "e_t", "rebound_deg", "spin_rad_s",
             pair ? fmt::format("{:>14} ", "spin2_rad_s") : "", "impulse", "contact_s", "stick", "slip");
  for (const ObliqueImpact& impact : impacts) {
    const ObliqueResult& r = impact.result;
    // The angle as given (89.999 stays 89.999), its shortest exact form.
    const std::string angle = fmt::format("{}", impact.angle_deg);
    if (!impact.solved()) {
      fmt::print("{:>9} {:11.5g}  failed: {}\n", angle, impact.initial_spin_rad_s, one_line(impact.failure));
      continue;
    }
    std::string modes;
    for (const ModeSwitch& m : r.switches)
      modes += fmt::format("{}{}", modes.empty() ? "" : ",", mode_name(m.mode));
    fmt::print(
        "{:>9} {:11.5g} {:14.10f} {:14.10f} {:12.6f} {:14.8g} {}{:12.8f} {:12.6g} {:10.4g} {:10.4g}  {}\n",
        angle, impact.initial_spin_rad_s, r.normal_restitution, r.tangential_restitution,
        r.rebound_angle_rad / kRadiansPerDegree, r.spin_first_rad_s,
        pair ? fmt::format("{:14.8g} ", r.spin_second_rad_s) : "", r.impulse_ratio, r.contact_time_s,
        r.stick_time_s / r.contact_time_s, r.slip_time_s / r.contact_time_s, modes);
  }
  fmt::print(
      "# e_t = -s'/s at the contact point (-1: unchanged); stick and slip as fractions of the contact "
      "time\n");
  fmt::print(
      "# eps and e_t within {:g}, rebound angle within {:g} rad, spin within {:g} of max(|spin|, v/R)\n",
      o.inputs.tolerance, o.inputs.tolerance, o.inputs.tolerance);
  for (const ObliqueImpact& impact : impacts) {
    if (impact.ill_conditioned) {
      fmt::print("# at {} deg, spin {:g} rad/s: {}\n", impact.angle_deg, impact.initial_spin_rad_s,
                 impact.conditioning);
    }
  }
}

// Maw's diagram of the sweep; without --out the script reads a scratch copy of the CSV beside the image.
void draw(const ObliqueCommandOptions& o, const Setup& s, const std::vector<ObliqueImpact>& impacts,
          const std::string& csv) {
  std::optional<files::ScratchFile> scratch;
  if (o.out.empty()) {
    scratch.emplace(o.plot, "data.csv", csv);  // also makes the image's folder
  } else if (const auto folder = std::filesystem::path(o.plot).parent_path(); !folder.empty()) {
    std::filesystem::create_directories(folder);
  }
  const std::filesystem::path data = scratch ? scratch->path() : std::filesystem::path(o.out);
  const MawModel model = s.tangential.friction > 0.0 ? maw_model(s) : MawModel{};
  if (!model.sticking_failure.empty()) {
    fmt::print(stderr, "restitution oblique: warning: the sticking limit is left out of the plot: {}\n",
               model.sticking_failure);
  }
  const std::string why = plot_maw(s, model, first_solved_restitution(impacts), data, o.plot,
                                   scene::plot_figure_formats(o.plot, o.format));
  if (!why.empty()) fmt::print(stderr, "{}", no_plot_warning("oblique", why));
}

int run(const ObliqueCommandOptions& o) {
  const Setup s = setup_of(o);
  if (s.rigid_wall) {
    // One release of notice for a changed meaning: the same words as `dem --wall` now give the same wall.
    fmt::print(stderr,
               "restitution oblique: note: --wall is a rigid wall, as in `dem --wall` (before, oblique's "
               "--wall was a wall of the sphere's own material: give --wall-young-modulus and "
               "--wall-poisson-ratio for that)\n");
  }
  if (!o.out.empty()) files::check_output_file(o.out);
  if (!o.plot.empty()) files::check_figure_file(o.plot, "--plot");
  if (!o.out.empty() && !o.plot.empty())
    files::check_outputs_apart({{"--out", o.out}, {"--plot", o.plot}}, {});
  const std::vector<ObliqueImpact> impacts = oblique_sweep(s);
  for (const ObliqueImpact& impact : impacts) {
    // Never silently: an outcome the tolerance cannot be shown for is said on stderr as well.
    if (impact.ill_conditioned) {
      fmt::print(stderr, "restitution oblique: warning: at {} deg, spin {:g} rad/s, {}\n", impact.angle_deg,
                 impact.initial_spin_rad_s, impact.conditioning);
    }
  }
  const std::string csv = oblique_csv(impacts);
  if (!o.out.empty()) files::write_file_atomically(o.out, csv);
  if (!o.plot.empty()) draw(o, s, impacts, csv);
  if (o.json) {
    print_json(o, s, impacts);
  } else {
    print_text(o, s, impacts);
  }
  // A failed impact loses none of the others: they are printed and written, it is marked, and the exit
  // status says that not every impact was solved (docs/cli.md).
  const std::size_t failed = failed_count(impacts);
  if (failed == 0) return 0;
  for (const ObliqueImpact& impact : impacts) {
    if (!impact.solved()) {
      fmt::print(stderr, "restitution oblique: numerical failure at {} deg, spin {:g} rad/s: {}\n",
                 impact.angle_deg, impact.initial_spin_rad_s, one_line(impact.failure));
    }
  }
  fmt::print(stderr,
             "restitution oblique: {} of {} impacts failed (marked failed); the {} solved are in the {}{}\n",
             failed, impacts.size(), impacts.size() - failed, o.json ? "JSON" : "table",
             o.out.empty() ? "" : " and " + o.out);
  return 1;
}

}  // namespace

void add_oblique_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<ObliqueCommandOptions>();
  CLI::App* cmd = app.add_subcommand("oblique",
                                     "oblique impacts with a LAMMPS or LIGGGHTS tangential model: tangential "
                                     "restitution, rebound angle, spin, stick/slip");
  add_material_options(*cmd, o->material);
  add_parameter_options(*cmd, oblique_fields(), o->inputs, [&](const ObliqueField& f, CLI::Option* option) {
    if (f.numbers == &ObliqueInputs::angles_deg) {
      cmd->add_option(
          "--angle-range", o->angle_range,
          "FROM:TO:N: N impact angles from FROM to TO degrees, evenly spaced (instead of --angle)");
    } else if (f.number == &ObliqueInputs::speed_m_s) {
      add_deprecated_alias(*cmd, option, "--speed");
    }
  });
  cmd->add_flag("--json", o->json, "print JSON instead of the table");
  cmd->add_option("--out", o->out, "also write the table as CSV to this file");
  CLI::Option* plot = add_plot_option(
      cmd, o->plot,
      "draw Maw, Barber & Fawcett's diagram (psi_2 against psi_1) to this file (needs friction > 0)");
  add_figure_format_option(cmd, o->format)->needs(plot);
  cmd->callback([o, &chosen] { chosen = [o] { return run(*o); }; });
}

}  // namespace restitution::cli
