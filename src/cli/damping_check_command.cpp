// `restitution damping-check`: the ε a DEM code's damping recipe really produces for a requested ε, per
// clamp and impact speed, and the map over requested ε (docs/damping.md).
#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/build_json.hpp"
#include "cli/commands.hpp"
#include "cli/json_writer.hpp"
#include "damping_check/check.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

using damping_check::CheckPoint;
using damping_check::CheckRequest;
using damping_check::CheckResult;

struct DampingCheckOptions {
  std::string recipe;
  std::optional<double> eps;
  std::string clamp = "both";
  double velocity = 1.0;  // reference speed of the speed-dependent recipes [m/s]
  double velocity_min = 0.1, velocity_max = 10.0;
  int points = 5;
  double tolerance = SolveOptions{}.tolerance;
  bool map = false;
  bool json = false;
};

CheckRequest request_of(const DampingCheckOptions& o, double eps) {
  CheckRequest r;
  r.recipe = damping_check::recipe_from_name(o.recipe);
  r.eps_requested = eps;
  r.clamps = damping_check::clamps_from_name(o.clamp);
  r.reference_velocity_m_s = o.velocity;
  r.speeds_m_s = damping_check::speed_grid(o.velocity_min, o.velocity_max, o.points);
  r.tolerance = o.tolerance;
  return r;
}

// The value, or null where there is none (no speed for a speed-independent recipe, no end).
void optional_field(JsonWriter& json, const char* name, const std::optional<double>& value) {
  json.key(name);
  if (value) {
    json.value(*value);
  } else {
    json.null();
  }
}

void write_points(JsonWriter& json, const CheckResult& r, double requested) {
  json.key("points").begin_array();
  for (const CheckPoint& p : r.points) {
    json.begin_object().field("clamp", damping_check::clamp_name(p.clamp));
    optional_field(json, "velocity_m_s", p.velocity_m_s);
    json.field("zeta", p.zeta);
    optional_field(json, "actual_eps", p.actual_eps);
    optional_field(json, "relative_error", p.relative_error(requested));
    json.end_object();
  }
  json.end_array();
}

void print_json(const DampingCheckOptions& o, const std::vector<double>& eps,
                const std::vector<CheckResult>& results) {
  const damping_check::RecipeSetting& s = results.front().setting;
  JsonWriter json;
  json.begin_object().field("recipe", damping_check::recipe_name(s.recipe));
  json.field("source", damping_check::recipe_source(s.recipe)).field("law", law_name(s.law));
  json.field("speed_independent", s.speed_independent()).field("clamp", o.clamp);
  json.field("reference_velocity_m_s", o.velocity);
  const auto entry = [&](std::size_t i) {
    json.field("requested_eps", eps[i])
        .field(results[i].setting.code_value_name, results[i].setting.code_value);
    json.field("zeta_reference", results[i].setting.zeta_reference);
    write_points(json, results[i], eps[i]);
  };
  if (o.map) {
    json.key("map").begin_array();
    for (std::size_t i = 0; i < eps.size(); ++i) {
      json.begin_object();
      entry(i);
      json.end_object();
    }
    json.end_array();
  } else {
    entry(0);
  }
  write_sundials_build(json);
  json.end_object();
  fmt::print("{}\n", json.str());
}

std::string speed_text(const CheckPoint& p) {
  return p.velocity_m_s ? fmt::format("{:.6g}", *p.velocity_m_s) : "any";
}

void print_text(const DampingCheckOptions& o, const std::vector<double>& eps,
                const std::vector<CheckResult>& results) {
  const damping_check::RecipeSetting& s = results.front().setting;
  fmt::print("# recipe {}: {}\n", damping_check::recipe_name(s.recipe),
             damping_check::recipe_source(s.recipe));
  fmt::print("# law member {} (natural units: x'' + zeta x^b x' + x^a = 0, x'(0) = 1)\n", law_name(s.law));
  if (s.speed_independent()) {
    fmt::print("# speed-independent: one eps for every impact speed, material and size\n");
  } else {
    fmt::print("# speed-dependent: zeta = zeta_ref (v / {:g} m/s)^(1/5), the same for every material\n",
               o.velocity);
  }
  if (!o.map) {
    fmt::print("# requested eps {}: {} = {:.10g}, zeta_ref = {:.10g}\n", eps[0], s.code_value_name,
               s.code_value, s.zeta_reference);
  }
  fmt::print("{:>13} {:>5} {:>10} {:>14} {:>14} {:>15}\n", "requested_eps", "clamp", "v_m_s", "zeta",
             "actual_eps", "relative_error");
  for (std::size_t i = 0; i < eps.size(); ++i) {
    for (const CheckPoint& p : results[i].points) {
      if (!p.actual_eps) {
        fmt::print("{:>13.6g} {:>5} {:>10} {:>14.8g}  none: overdamped, the overlap never returns to 0\n",
                   eps[i], damping_check::clamp_name(p.clamp), speed_text(p), p.zeta);
        continue;
      }
      fmt::print("{:>13.6g} {:>5} {:>10} {:>14.8g} {:>14.10f} {:>+15.6e}\n", eps[i],
                 damping_check::clamp_name(p.clamp), speed_text(p), p.zeta, *p.actual_eps,
                 *p.relative_error(eps[i]));
    }
  }
}

int run(const DampingCheckOptions& o) {
  if (o.map == o.eps.has_value()) {
    throw InvalidInput("give either --eps E (one requested eps) or --map (requested eps from 0.05 to 0.99)");
  }
  const std::vector<double> eps = o.map ? damping_check::map_eps_grid() : std::vector<double>{*o.eps};
  CollisionSolver solver;
  std::vector<CheckResult> results;
  results.reserve(eps.size());
  for (double e : eps) results.push_back(damping_check::check_recipe(request_of(o, e), solver));
  if (o.json) {
    print_json(o, eps, results);
  } else {
    print_text(o, eps, results);
  }
  return 0;
}

}  // namespace

void add_damping_check_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<DampingCheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "damping-check",
      "the eps a DEM code's damping recipe really gives for a requested eps, clamp on and off");
  cmd->add_option("--recipe", o->recipe, "recipe: " + damping_check::recipe_names())->required();
  cmd->add_option("--eps", o->eps, "requested coefficient of restitution in (0, 1)");
  cmd->add_flag("--map", o->map, "check the requested eps 0.05, 0.10, ..., 0.95, 0.99 instead of --eps");
  cmd->add_option("--clamp", o->clamp,
                  "force clamped at zero: on (delayed-recovery end), off (naive end) or both")
      ->capture_default_str();
  cmd->add_option("--velocity", o->velocity,
                  "reference impact speed in m/s the speed-dependent recipes are set up at (YADE's vn)")
      ->capture_default_str();
  cmd->add_option("--velocity-min", o->velocity_min, "smallest impact speed in m/s")->capture_default_str();
  cmd->add_option("--velocity-max", o->velocity_max, "largest impact speed in m/s")->capture_default_str();
  cmd->add_option("--points", o->points, "impact speeds, log-spaced (speed-dependent recipes)")
      ->capture_default_str();
  cmd->add_option("--tolerance", o->tolerance, "accuracy of each eps, in [1e-11, 1e-2]")
      ->capture_default_str();
  cmd->add_flag("--json", o->json, "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, &chosen] { chosen = [o] { return run(*o); }; });
}

}  // namespace restitution::cli
