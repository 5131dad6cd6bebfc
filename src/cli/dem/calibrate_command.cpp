// SPDX-License-Identifier: BSD-3-Clause
// `restitution calibrate`: β (and A for a material, and the 1999 paper's g*) from one measured ε at one
// impact speed.
#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/adhesion_options.hpp"
#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/material_options.hpp"
#include "cli/common/options.hpp"
#include "cli/common/result_json.hpp"
#include "cli/dem/calibrate_adhesion.hpp"
#include "cli/dem/from_fit.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

// The methods of the collision solver, and the fast table.
constexpr const char* kFastMethod = "fast";
std::vector<std::string> calibration_methods() {
  std::vector<std::string> names = method_names();
  names.emplace_back(kFastMethod);
  return names;
}

struct CalibrateOptions {
  std::string law = law_name(LawKind::viscoelastic_hertz);
  double eps = 0.0;
  double velocity = 0.0;
  std::string end = end_name(CalibrationRequest{}.end);
  double tolerance = CalibrationRequest{}.tolerance;
  std::string method = method_name(CalibrationRequest{}.method);
  MaterialOptions material;
  AdhesionOptions adhesion;  // the damping of an adhesive contact instead (calibrate_adhesion.hpp)
  std::optional<double> sticking_speed;  // with --adhesion: γ and the damping from it and ε
  bool json = false;
  std::string from_fit;  // fit-data --out FILE: beta and its intervals instead of --eps
  bool end_given = false;
};

std::optional<double> material_k(const CalibrateOptions& o) {
  if (!o.material.any()) return std::nullopt;
  return elastic_constants(material_from(o.material)).k;
}

int run_calibrate(const CalibrateOptions& o) {
  if (o.adhesion.any() || o.sticking_speed) {
    if (!o.from_fit.empty() || o.end_given || o.method == kFastMethod ||
        o.law != law_name(LawKind::viscoelastic_hertz)) {
      throw InvalidInput(
          "--adhesion takes the material, --surface-energy or --sticking-speed, --eps, --velocity and "
          "--tolerance: not "
          "--from-fit, "
          "--end, --law or --method fast");
    }
    return run_adhesive_calibrate(o.adhesion, o.material, o.eps, o.velocity, o.sticking_speed, o.tolerance,
                                  o.json);
  }
  if (!o.from_fit.empty()) {
    if (o.eps != 0.0) throw InvalidInput("--from-fit and --eps exclude each other");
    if (law_from_name(o.law) != LawKind::viscoelastic_hertz) {
      throw InvalidInput(fmt::format("--from-fit carries a viscoelastic Hertz fit, not --law {}", o.law));
    }
    const std::optional<CollisionEnd> end =
        o.end_given ? std::optional<CollisionEnd>(end_from_name(o.end)) : std::nullopt;
    return calibrate_from_fit(o.from_fit, end, o.velocity, material_k(o), o.json);
  }
  if (o.eps == 0.0) throw InvalidInput("--eps is required (or --from-fit FILE)");
  CalibrationRequest request;
  request.law = law_from_name(o.law);
  const bool hertz = has_dissipative_constant(request.law);
  if (!hertz && o.material.any()) {
    throw InvalidInput(
        fmt::format("a material gives A for --law viscoelastic-hertz only, not --law {}", o.law));
  }
  request.eps = o.eps;
  request.velocity_m_s = o.velocity;
  request.end = end_from_name(o.end);
  request.tolerance = o.tolerance;
  request.fast = o.method == kFastMethod;
  if (!request.fast) request.method = method_from_name(o.method);
  request.k = material_k(o);
  CollisionSolver solver;
  const Calibration c = calibrate(request, solver);
  if (o.json) {
    JsonWriter json;
    json.begin_object();
    if (!hertz) json.field("law", o.law);
    json.field("eps", o.eps).field("velocity_m_s", o.velocity).field("end", end_name(request.end));
    json.field("method", o.method);
    if (!request.fast) json.field("tolerance", o.tolerance);
    json.field("zeta", c.zeta);
    const LawParameter parameter = law_parameter(request.law);
    if (parameter.zeta_per_parameter != 1.0) json.field(parameter_key(request.law), c.parameter);
    if (hertz) json.field("beta", c.beta);
    json.field("eps_at_zeta", c.eps_at_zeta);
    if (hertz) json.field("characteristic_velocity_m_s", c.characteristic_velocity_m_s);
    if (request.k) json.field("k", *request.k);
    if (c.dissipative_constant_s) json.field("dissipative_constant_s", *c.dissipative_constant_s);
    json.field("solves", c.solves);
    fmt::print("{}\n", finish_json_document(json));
    return 0;
  }
  fmt::print("calibration: eps = {} at v = {} m/s, {} end ({})\n", o.eps, o.velocity, end_name(request.end),
             request.fast ? std::string("fast table, 1e-13") : fmt::format("tolerance {:g}", o.tolerance));
  if (!hertz) {
    fmt::print("  law {}: zeta = {:.12g} ({} = {:.12g})\n", o.law, c.zeta, law_parameter(request.law).name,
               c.parameter);
    fmt::print("  eps(zeta), re-solved         {:.12g}\n  {} collisions integrated\n", c.eps_at_zeta,
               c.solves);
    return 0;
  }
  fmt::print("  zeta = beta v^(1/5)         {:.12g}\n", c.zeta);
  fmt::print("  beta                        {:.12g} s^(1/5) m^(-1/5)\n", c.beta);
  fmt::print("  eps(zeta), {:<17}{:.12g}\n", request.fast ? "fast table" : "re-solved", c.eps_at_zeta);
  fmt::print("  g* (1999 paper, Eq. 31)     {:.12g} m/s\n", c.characteristic_velocity_m_s);
  if (c.dissipative_constant_s) {
    fmt::print("  k = rho/m_eff               {:.12g} s^-2 m^-1/2\n", *request.k);
    fmt::print("  A (dissipative constant)    {:.12g} s\n", *c.dissipative_constant_s);
  }
  fmt::print("  {} collisions integrated\n", c.solves);
  return 0;
}

}  // namespace

void add_calibrate_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<CalibrateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "calibrate", "beta (and A for a material, and the 1999 g*) from a measured eps at one impact speed");
  add_law_option(*cmd, o->law);
  cmd->add_option("--eps", o->eps, "measured coefficient of restitution, in (0, 1)");
  cmd->add_option(
      "--from-fit", o->from_fit,
      "instead of --eps: the JSON of fit-data --out; beta, eps at --velocity and A with the "
      "intervals the fit carries over (the Hertz fit with the lowest AIC, or at --end if given; one the fit "
      "itself rejects is said so, without intervals)");
  cmd->add_option("--velocity", o->velocity, "impact speed v > 0 in m/s")->required();
  cmd->add_option("--end", o->end, "end of the collision the measurement corresponds to")
      ->check(CLI::IsMember(end_names()))
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance,
                  "accuracy of each eps, in [1e-11, 1e-2] (taylor: [1e-13, 1e-2])")
      ->capture_default_str();
  cmd->add_option("--method", o->method,
                  "integration method: " + method_choices([](Method method) {
                    return method == Method::taylor ? "the naive end only for zeta <= 100" : "";
                  }) +
                      "; or fast: the certified table (restitution/fast.hpp, 1e-13, no integration, any eps "
                      "in (0, 1))")
      ->check(CLI::IsMember(calibration_methods()))
      ->capture_default_str();
  add_material_options(*cmd, o->material);
  add_adhesion_options(*cmd, o->adhesion);
  cmd->add_option(
      "--sticking-speed", o->sticking_speed,
      "with --adhesion jkr|jkr-lammps|dmt, instead of --surface-energy: the measured sticking speed "
      "v_s < --velocity in m/s; the surface energy and the damping are calibrated together");
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, cmd, &chosen] {
    o->end_given = cmd->count("--end") > 0;
    chosen = [o] { return run_calibrate(*o); };
  });
}

}  // namespace restitution::cli
