// SPDX-License-Identifier: BSD-3-Clause
// `restitution oblique`: oblique impacts of two spheres of one material, or of a sphere on a wall, with a
// LAMMPS `pair granular` tangential model: the tangential restitution, rebound angle, spin, impulse ratio and
// the stick/slip history per impact angle (src/oblique/, docs/oblique.md).
#include <fmt/core.h>

#include <cmath>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/output_files.hpp"
#include "oblique/oblique_contact.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/solve_types.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {
namespace {

using namespace restitution::oblique;

struct ObliqueCommandOptions {
  MaterialOptions material;
  double dissipative_constant = 0.0;
  bool wall = false;
  bool fixed_normal = false;
  std::string tangential = "linear_history";
  std::optional<double> tangential_stiffness;
  double tangential_damping = 0.0;
  std::optional<double> friction;
  std::vector<double> angles_deg;
  double speed = 1.0;
  double spin = 0.0;
  std::string end = "delayed-recovery";
  std::string torque_arm = "lammps";
  double tolerance = 1e-10;
  bool json = false;
  std::string out;
};

struct Setup {
  ObliqueGeometry geometry;
  NormalForce normal;
  TangentialForce tangential;
  ObliqueOptions options;
  double effective_modulus_pa = 0.0;
};

constexpr double kDegree = std::numbers::pi / 180.0;

Setup setup_of(const ObliqueCommandOptions& o) {
  const Material m = material_from(o.material);
  if (!(o.dissipative_constant >= 0.0) || !std::isfinite(o.dissipative_constant)) {
    throw InvalidInput(fmt::format("--dissipative-constant must be a non-negative number of seconds, got {}",
                                   o.dissipative_constant));
  }
  if (!o.friction) throw InvalidInput("give --friction MU (0 for a frictionless contact)");
  if (o.wall && (o.material.radius2 || o.material.mass2)) {
    throw InvalidInput("--wall takes one sphere: drop --radius2 and --mass2");
  }
  Setup s;
  const auto mass = [&](double radius, const std::optional<double>& given) {
    return given ? *given : sphere_mass_kg(radius, *m.density_kg_m3);
  };
  s.geometry.first = solid_sphere(m.radius1_m, mass(m.radius1_m, m.mass1_kg));
  if (!o.wall) s.geometry.second = solid_sphere(m.radius2_m, mass(m.radius2_m, m.mass2_kg));
  s.geometry.fixed_normal = o.fixed_normal;
  // "lammps": what LAMMPS does, R - δ/2 for a pair (pair_granular.cpp:663), R for a wall
  // (fix_wall_gran.cpp:1512).
  const bool half_overlap =
      o.torque_arm == "radius-minus-half-overlap" || (o.torque_arm == "lammps" && !o.wall);
  s.geometry.torque_arm = half_overlap ? TorqueArm::radius_minus_half_overlap : TorqueArm::radius;
  s.effective_modulus_pa = effective_modulus_pa(m.young_modulus_pa, m.poisson_ratio);
  // F = ρ δ^{3/2} + (3/2) A ρ sqrt(δ) δ', ρ = (4/3) E* sqrt(R*): a wall of the sphere's material has the same
  // E*.
  const double rho = hertz_stiffness(s.effective_modulus_pa, effective_radius_m(s.geometry));
  s.normal = {LawKind::viscoelastic_hertz, rho, 1.5 * o.dissipative_constant * rho};
  s.tangential.kind = tangential_from_name(o.tangential);
  s.tangential.damping_factor = o.tangential_damping;
  s.tangential.friction = *o.friction;
  if (o.tangential_stiffness) {
    s.tangential.stiffness = *o.tangential_stiffness;
  } else if (s.tangential.kind == TangentialKind::mindlin) {
    // LAMMPS's `mindlin NULL`: 8 G* with 1/G* = 2 · 2(2 - ν)(1 + ν)/E for two spheres of one material
    // (pair_granular.cpp:1021-1023, mix_stiffnessG at line 1790).
    const double nu = m.poisson_ratio;
    s.tangential.stiffness = 8.0 * m.young_modulus_pa / (4.0 * (2.0 - nu) * (1.0 + nu));
  } else if (s.tangential.kind == TangentialKind::linear_history) {
    throw InvalidInput("linear_history needs --tangential-stiffness K_T in N/m");
  }
  s.options.end = end_from_name(o.end);
  s.options.relative_tolerance = o.tolerance;
  if (o.angles_deg.empty())
    throw InvalidInput("give --angle DEG (one or more impact angles from the normal)");
  for (const double a : o.angles_deg) {
    if (!(a >= 0.0 && a < 90.0)) {
      throw InvalidInput(fmt::format("--angle must be in [0, 90) degrees from the normal, got {}", a));
    }
  }
  if (!(o.speed > 0.0) || !std::isfinite(o.speed)) {
    throw InvalidInput(fmt::format("--speed must be a positive number of m/s, got {}", o.speed));
  }
  return s;
}

ImpactVelocity impact_at(const ObliqueCommandOptions& o, double angle_deg) {
  return {o.speed * std::cos(angle_deg * kDegree), o.speed * std::sin(angle_deg * kDegree), o.spin, 0.0};
}

const char* kColumns =
    "angle_deg,normal_restitution,tangential_restitution,rebound_angle_deg,spin_rad_s,impulse_ratio,"
    "contact_time_s,stick_time_s,slip_time_s,switches";

std::string csv_row(double angle, const ObliqueResult& r) {
  return fmt::format("{},{},{},{},{},{},{},{},{},{}\n", number17(angle), number17(r.normal_restitution),
                     number17(r.tangential_restitution), number17(r.rebound_angle_rad / kDegree),
                     number17(r.spin_first_rad_s), number17(r.impulse_ratio), number17(r.contact_time_s),
                     number17(r.stick_time_s), number17(r.slip_time_s), r.switches.size() - 1);
}

void print_json(const ObliqueCommandOptions& o, const Setup& s, const std::vector<ObliqueResult>& results) {
  JsonWriter json;
  json.begin_object().field("tangential_model", tangential_name(s.tangential.kind));
  json.field("contact", o.wall ? "sphere-wall" : "sphere-sphere").field("end", o.end);
  json.field("torque_arm", o.torque_arm).field("fixed_normal", o.wall || o.fixed_normal);
  json.field("normal_stiffness_N_m1_5", s.normal.stiffness)
      .field("normal_damping_N_s_m1_5", s.normal.damping);
  json.field("tangential_stiffness", s.tangential.stiffness);
  json.field("tangential_damping_factor", s.tangential.damping_factor)
      .field("friction", s.tangential.friction);
  json.field("speed_m_s", o.speed).field("initial_spin_rad_s", o.spin).field("tolerance", o.tolerance);
  json.key("impacts").begin_array();
  for (std::size_t i = 0; i < results.size(); ++i) {
    const ObliqueResult& r = results[i];
    json.begin_object().field("angle_deg", o.angles_deg[i]);
    json.field("normal_restitution", r.normal_restitution);
    json.key("tangential_restitution");
    if (std::isfinite(r.tangential_restitution)) {
      json.value(r.tangential_restitution);
    } else {
      json.null();  // no slip at impact: e_t is undefined
    }
    json.field("rebound_angle_deg", r.rebound_angle_rad / kDegree);
    json.field("spin_rad_s", r.spin_first_rad_s);
    if (!o.wall) json.field("spin2_rad_s", r.spin_second_rad_s);
    json.field("impulse_ratio", r.impulse_ratio).field("contact_time_s", r.contact_time_s);
    if (!o.wall) json.field("line_of_centres_turn_deg", r.line_of_centres_turn_rad / kDegree);
    json.field("stick_time_s", r.stick_time_s).field("slip_time_s", r.slip_time_s);
    json.key("modes").begin_array();
    for (const ModeSwitch& m : r.switches) {
      json.begin_object().field("time_s", m.time_s).field("mode", mode_name(m.mode)).end_object();
    }
    json.end_array();
    json.field("steps", r.stats.steps);
    json.end_object();
  }
  json.end_array();
  fmt::print("{}\n", finish_json_document(json));
}

void print_text(const ObliqueCommandOptions& o, const Setup& s, const std::vector<ObliqueResult>& results) {
  fmt::print(
      "# oblique impact, {}: viscoelastic Hertz k = {:.10g} N/m^1.5, gamma = {:.10g} N s/m^1.5, {} end\n",
      o.wall ? "sphere on a wall" : "two spheres", s.normal.stiffness, s.normal.damping, o.end);
  fmt::print(
      "# tangential {} (LAMMPS pair granular): k_t = {:.10g} {}, damping {:.6g}, friction {:.6g}; "
      "speed {:g} m/s, initial spin {:g} rad/s\n",
      tangential_name(s.tangential.kind), s.tangential.stiffness,
      s.tangential.kind == TangentialKind::mindlin ? "N/m^2 (times sqrt(R* delta))" : "N/m",
      s.tangential.damping_factor, s.tangential.friction, o.speed, o.spin);
  fmt::print("{:>9} {:>14} {:>14} {:>12} {:>14} {:>12} {:>12} {:>10} {:>10}  modes\n", "angle_deg", "eps_n",
             "e_t", "rebound_deg", "spin_rad_s", "impulse", "contact_s", "stick", "slip");
  for (std::size_t i = 0; i < results.size(); ++i) {
    const ObliqueResult& r = results[i];
    std::string modes;
    for (const ModeSwitch& m : r.switches)
      modes += fmt::format("{}{}", modes.empty() ? "" : ",", mode_name(m.mode));
    fmt::print("{:9.4g} {:14.10f} {:14.10f} {:12.6f} {:14.8g} {:12.8f} {:12.6g} {:10.4g} {:10.4g}  {}\n",
               o.angles_deg[i], r.normal_restitution, r.tangential_restitution, r.rebound_angle_rad / kDegree,
               r.spin_first_rad_s, r.impulse_ratio, r.contact_time_s, r.stick_time_s / r.contact_time_s,
               r.slip_time_s / r.contact_time_s, modes);
  }
  fmt::print(
      "# e_t = -s'/s at the contact point (-1: unchanged); stick and slip as fractions of the contact "
      "time\n");
}

int run(const ObliqueCommandOptions& o) {
  const Setup s = setup_of(o);
  if (!o.out.empty()) check_output_file(o.out);
  std::vector<ObliqueResult> results;
  results.reserve(o.angles_deg.size());
  for (const double angle : o.angles_deg) {
    results.push_back(solve_oblique(s.geometry, s.normal, s.tangential, impact_at(o, angle), s.options));
  }
  if (!o.out.empty()) {
    std::string csv = std::string(kColumns) + "\n";
    for (std::size_t i = 0; i < results.size(); ++i) csv += csv_row(o.angles_deg[i], results[i]);
    write_file_atomically(o.out, csv);
  }
  if (o.json) {
    print_json(o, s, results);
  } else {
    print_text(o, s, results);
  }
  return 0;
}

}  // namespace

void add_oblique_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<ObliqueCommandOptions>();
  CLI::App* cmd = app.add_subcommand("oblique",
                                     "oblique impacts with a LAMMPS tangential model: tangential "
                                     "restitution, rebound angle, spin, stick/slip");
  add_material_options(*cmd, o->material);
  cmd->add_option("--dissipative-constant", o->dissipative_constant, "the dissipative constant A in s")
      ->capture_default_str();
  cmd->add_flag("--wall", o->wall, "a sphere on a flat wall of the same material instead of two spheres");
  cmd->add_flag(
      "--fixed-normal", o->fixed_normal,
      "two spheres: keep the normal of the impact (the textbook model) instead of letting the line of "
      "centres turn as in LAMMPS");
  cmd->add_option("--tangential", o->tangential,
                  "tangential model: linear_nohistory, linear_history or mindlin")
      ->check(CLI::IsMember(tangential_names()))
      ->capture_default_str();
  cmd->add_option("--tangential-stiffness", o->tangential_stiffness,
                  "k_t: N/m for linear_history, N/m^2 for mindlin (default there: LAMMPS's NULL, 8 G*)");
  cmd->add_option("--tangential-damping", o->tangential_damping,
                  "LAMMPS's tangential damping factor (times the normal damping coefficient)")
      ->capture_default_str();
  cmd->add_option("--friction", o->friction, "Coulomb friction coefficient mu");
  cmd->add_option("--angle", o->angles_deg, "impact angle(s) from the normal in degrees, in [0, 90)")
      ->delimiter(',');
  cmd->add_option("--speed", o->speed, "impact speed in m/s")->capture_default_str();
  cmd->add_option("--spin", o->spin,
                  "initial spin of the (first) sphere in rad/s (positive adds to the slip)")
      ->capture_default_str();
  cmd->add_option("--end", o->end,
                  "end of the collision: naive (no clamp) or delayed-recovery (force clamped)")
      ->check(CLI::IsMember(end_names()))
      ->capture_default_str();
  cmd->add_option("--torque-arm", o->torque_arm,
                  "lammps (R - delta/2 for a pair, R for a wall), radius or radius-minus-half-overlap")
      ->check(CLI::IsMember({"lammps", "radius", "radius-minus-half-overlap"}))
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance, "CVODE's relative tolerance, in [1e-14, 1e-2]")
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print JSON instead of the table");
  cmd->add_option("--out", o->out, "also write the table as CSV to this file");
  cmd->callback([o, &chosen] { chosen = [o] { return run(*o); }; });
}

}  // namespace restitution::cli
