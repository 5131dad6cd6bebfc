// `restitution calibrate`: β (and A for a material, and the 1999 paper's g*) from one measured ε at one
// impact speed.
#include <fmt/core.h>

#include <memory>
#include <optional>

#include "cli/commands.hpp"
#include "cli/json_writer.hpp"
#include "cli/options.hpp"
#include "restitution/calibration.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {
namespace {

struct CalibrateOptions {
  double eps = 0.0;
  double velocity = 0.0;
  std::string end = "delayed-recovery";
  double tolerance = 1e-10;
  std::string method = "auto";
  std::optional<double> young_modulus, poisson_ratio, radius, radius2, density, mass, mass2;
  bool json = false;
};

std::optional<double> material_k(const CalibrateOptions& o) {
  const bool any =
      o.young_modulus || o.poisson_ratio || o.radius || o.radius2 || o.density || o.mass || o.mass2;
  if (!any) return std::nullopt;
  if (!o.young_modulus || !o.poisson_ratio || !o.radius) {
    throw InvalidInput(
        "a material needs --young-modulus, --poisson-ratio and --radius (and --density or --mass)");
  }
  Material m;
  m.young_modulus_pa = *o.young_modulus;
  m.poisson_ratio = *o.poisson_ratio;
  m.radius1_m = *o.radius;
  m.radius2_m = o.radius2.value_or(*o.radius);
  m.density_kg_m3 = o.density;
  if (o.mass) {
    m.mass1_kg = o.mass;
    m.mass2_kg = o.mass2.value_or(*o.mass);
  } else if (o.mass2) {
    throw InvalidInput("--mass2 needs --mass");
  }
  return elastic_constants(m).k;
}

int run_calibrate(const CalibrateOptions& o) {
  CalibrationRequest request;
  request.eps = o.eps;
  request.velocity_m_s = o.velocity;
  request.end = o.end == "naive" ? CollisionEnd::naive : CollisionEnd::delayed_recovery;
  request.tolerance = o.tolerance;
  request.fast = o.method == "fast";
  if (!request.fast) request.method = method_from(o.method);
  request.k = material_k(o);
  CollisionSolver solver;
  const Calibration c = calibrate(request, solver);
  if (o.json) {
    JsonWriter json;
    json.begin_object();
    json.field("eps", o.eps).field("velocity_m_s", o.velocity).field("end", end_name(request.end));
    json.field("method", o.method);
    if (!request.fast) json.field("tolerance", o.tolerance);
    json.field("zeta", c.zeta).field("beta", c.beta).field("eps_at_zeta", c.eps_at_zeta);
    json.field("characteristic_velocity_m_s", c.characteristic_velocity_m_s);
    if (request.k) json.field("k", *request.k);
    if (c.dissipative_constant_s) json.field("dissipative_constant_s", *c.dissipative_constant_s);
    json.field("solves", c.solves);
    json.end_object();
    fmt::print("{}\n", json.str());
    return 0;
  }
  fmt::print("calibration: eps = {} at v = {} m/s, {} end ({})\n", o.eps, o.velocity, end_name(request.end),
             request.fast ? std::string("fast table, 1e-13") : fmt::format("tolerance {:g}", o.tolerance));
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
  cmd->add_option("--eps", o->eps, "measured coefficient of restitution, in (0, 1)")->required();
  cmd->add_option("--velocity", o->velocity, "impact speed v > 0 in m/s")->required();
  cmd->add_option("--end", o->end, "end of the collision the measurement corresponds to")
      ->check(CLI::IsMember({"naive", "delayed-recovery"}))
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance, "accuracy of each eps, in [1e-11, 1e-2]")
      ->capture_default_str();
  cmd->add_option(
         "--method", o->method,
         "integration method: bdf, adams or auto; or fast: the certified table (restitution/fast.hpp, "
         "1e-13, no integration, any eps in (0, 1))")
      ->check(CLI::IsMember({"bdf", "adams", "auto", "fast"}))
      ->capture_default_str();
  cmd->add_option("--young-modulus", o->young_modulus, "material: Young's modulus Y in Pa");
  cmd->add_option("--poisson-ratio", o->poisson_ratio, "material: Poisson ratio in (-1, 0.5)");
  cmd->add_option("--radius", o->radius, "material: sphere radius in m (both spheres unless --radius2)");
  cmd->add_option("--radius2", o->radius2, "material: radius of the second sphere in m");
  cmd->add_option("--density", o->density, "material: density in kg/m^3 (gives the masses)");
  cmd->add_option("--mass", o->mass, "material: sphere mass in kg (instead of --density)");
  cmd->add_option("--mass2", o->mass2, "material: mass of the second sphere in kg");
  cmd->add_flag("--json", o->json, "print one JSON object (17 significant digits)");
  cmd->callback([o, &chosen] { chosen = [o] { return run_calibrate(*o); }; });
}

}  // namespace restitution::cli
