// SPDX-License-Identifier: BSD-3-Clause
#include "cli/dem/dem_oblique.hpp"

#include <fmt/core.h>

#include <cmath>

#include "cli/common/deprecated_alias.hpp"
#include "dem/dem_codes.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

void warn_ill_conditioned(const DemOblique& r, const std::vector<ContractedOblique>& impacts) {
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    if (impacts[i].ill_conditioned) {
      fmt::print(stderr, "restitution dem: warning: oblique impact at {} deg, {}\n", r.angles_deg[i],
                 impacts[i].conditioning);
    }
  }
}

void write_impacts(JsonWriter& json, const DemOblique& r, const std::vector<ContractedOblique>& impacts) {
  json.begin_array();
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const ObliqueResult& x = impacts[i].result;
    json.begin_object().field("angle_deg", r.angles_deg[i]).field("normal_restitution", x.normal_restitution);
    json.key("tangential_restitution");
    if (std::isfinite(x.tangential_restitution)) {
      json.value(x.tangential_restitution);
    } else {
      json.null();  // no slip at impact: e_t is undefined
    }
    json.field("rebound_angle_deg", x.rebound_angle_rad / kRadiansPerDegree)
        .field("spin_rad_s", x.spin_first_rad_s);
    if (r.geometry.second) json.field("spin2_rad_s", x.spin_second_rad_s);
    json.field("contact_time_s", x.contact_time_s).field("conditioning", impacts[i].conditioning);
    json.end_object();
  }
  json.end_array();
}

void print_impacts(const DemOblique& r, const std::vector<ContractedOblique>& impacts, const char* c) {
  const bool pair = r.geometry.second.has_value();  // the second sphere spins too
  fmt::print("{}   {:>9} {:>14} {:>14} {:>12} {:>14}{}\n", c, "angle_deg", "eps_n", "e_t", "rebound_deg",
             "spin_rad_s", pair ? fmt::format(" {:>14}", "spin2_rad_s") : "");
  for (std::size_t i = 0; i < impacts.size(); ++i) {
    const ObliqueResult& x = impacts[i].result;
    // The angle as given, in its shortest exact form (89.999 is not 90).
    fmt::print("{}   {:>9} {:14.10f} {:14.10f} {:12.6f} {:14.8g}{}{}\n", c,
               fmt::format("{}", r.angles_deg[i]), x.normal_restitution, x.tangential_restitution,
               x.rebound_angle_rad / kRadiansPerDegree, x.spin_first_rad_s,
               pair ? fmt::format(" {:14.8g}", x.spin_second_rad_s) : "",
               impacts[i].ill_conditioned ? "  (" + impacts[i].conditioning + ")" : "");
  }
}

}  // namespace

void add_dem_oblique_options(CLI::App& command, DemObliqueOptions& o) {
  command
      .add_option("--tangential", o.tangential,
                  "with --friction (lammps): LAMMPS's tangential model of the printed line, its oblique "
                  "outputs and --target-et: " +
                      alternatives(tangential_names_of("lammps")))
      ->check(CLI::IsMember(tangential_names_of("lammps")))
      ->capture_default_str();
  command.add_option("--tangential-stiffness", o.tangential_stiffness,
                     "k_t of --tangential in N/m (mindlin: N/m^2, its stiffness is k_t a; default NULL, 8 G* "
                     "for a pair); required by linear_history");
  command.add_option("--tangential-damping", o.tangential_damping,
                     "x_gamma_t of --tangential: the tangential damping coefficient over the normal one "
                     "(default 1)");
  CLI::Option* angle =
      command
          .add_option("--angle", o.angles_deg,
                      "with --friction (lammps, liggghts; yade's 2023.02a lines): the impact angle(s) from "
                      "the normal in "
                      "degrees, in [0, 90), at which to report what the lines give oblique impacts (default "
                      "5,15,30,45,60,80)")
          ->delimiter(',');
  add_deprecated_alias(command, angle, "--angles");
  command
      .add_option("--et-accuracy", o.et_accuracy,
                  "the accuracy of e_t the code's (LAMMPS's, LIGGGHTS's, YADE's) steps per contact are "
                  "reported for, in (0, 0.1]")
      ->capture_default_str();
  command.add_option(
      "--target-et", o.target_et,
      "with --reference-angle (lammps, liggghts; --friction): find --tangential's parameter (k_t, "
      "or linear_nohistory's x_gamma_t; liggghts: kt) that gives this tangential restitution "
      "e_t at that angle, and print its line");
  command.add_option("--reference-angle", o.reference_angle_deg,
                     "the impact angle in degrees from the normal at which --target-et holds, in (0, 90)");
}

void warn_oblique(const DemOblique& r) {
  warn_ill_conditioned(r, r.impacts);
  warn_ill_conditioned(r, r.inverse_impacts);
}

void print_oblique_text(const DemOblique& r, const char* c) {
  fmt::print(
      "{} oblique impacts these lines give at {:g} m/s (tangential {}; e_t = -s'/s at the contact point, "
      "eps and e_t within {:g}):\n",
      c, r.speed_m_s, r.tangential_words, r.tolerance);
  print_impacts(r, r.impacts, c);
  if (r.tangential.friction == 0.0) {
    // No cap and no tangential force: neither the cap rule nor the steps e_t needs mean anything.
    fmt::print(
        "{} frictionless lines: no tangential force, e_t = -1 and the spins unchanged at every angle\n", c);
    return;
  }
  const TangentialModel& model = tangential_model(r.tangential.kind);
  fmt::print("{} {}'s rule: {}\n", c, model.code_title, model.cap_rule);
  fmt::print(
      "{} {} decides stick or slip once per step and is first order in dt: e_t within {:g} needs {:g} "
      "steps per contact (|error| <= {:g}/N, a bound over Debian's {} measured; docs/dem.md), timestep <= "
      "{:.4g} s for the shortest "
      "contact here\n",
      c, model.code_title, r.et_accuracy, r.steps_per_contact, r.error_coefficient, model.code_title,
      r.timestep_s);
  if (!r.inverse) return;
  fmt::print(
      "{} for e_t = {:g} at {:g} deg: {} = {:.10g} (e_t there {:.10f}; reachable by this parameter: [{:.6g}, "
      "{:.6g}]), the line:\n",
      c, r.target_et, r.reference_angle_deg, r.inverse->parameter_name, r.inverse->parameter,
      r.inverse->check.result.tangential_restitution, r.inverse->lowest_reachable_et,
      r.inverse->highest_reachable_et);
  for (const auto& line : r.inverse_lines) fmt::print("{}\n", line);
  fmt::print("{} which gives:\n", c);
  print_impacts(r, r.inverse_impacts, c);
}

void write_oblique_json(JsonWriter& json, const DemOblique& r) {
  json.key("oblique").begin_object();
  json.field("tangential", r.tangential_words).field("tangential_model", tangential_name(r.tangential.kind));
  json.field("tangential_stiffness", r.tangential.stiffness)
      .field("tangential_damping_factor", r.tangential.damping_factor);
  json.field("speed_m_s", r.speed_m_s).field("tolerance", r.tolerance);
  json.field("code", dem::code_name(r.code));
  const bool frictionless = r.tangential.friction == 0.0;  // no cap rule, no steps for e_t
  if (!frictionless) json.field("cap_rule", tangential_model(r.tangential.kind).cap_rule);
  json.key("impacts");
  write_impacts(json, r, r.impacts);
  if (!frictionless) {
    json.key(fmt::format("{}_steps", dem::code_name(r.code))).begin_object();
    json.field("et_accuracy", r.et_accuracy).field("error_coefficient", r.error_coefficient);
    json.field("steps_per_contact", r.steps_per_contact).field("timestep_s", r.timestep_s).end_object();
  }
  if (r.inverse) {
    json.key("inverse").begin_object();
    json.field("target_et", r.target_et).field("reference_angle_deg", r.reference_angle_deg);
    json.field("parameter", r.inverse->parameter_name).field("value", r.inverse->parameter);
    json.field("tangential_restitution", r.inverse->check.result.tangential_restitution);
    json.key("reachable_et").begin_array().value(r.inverse->lowest_reachable_et);
    json.value(r.inverse->highest_reachable_et).end_array();
    json.field("lines", r.inverse_lines);
    json.key("impacts");
    write_impacts(json, r, r.inverse_impacts);
    json.end_object();
  }
  json.end_object();
}

}  // namespace restitution::cli
