// SPDX-License-Identifier: BSD-3-Clause
// `restitution damping-check`: the ε a DEM code's damping recipe really produces for a requested ε, per
// clamp and impact speed, and the map over requested ε (docs/damping.md).
#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/deprecated_alias.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/parameter_options.hpp"
#include "cli/common/range_option.hpp"
#include "damping_check/check.hpp"
#include "damping_check/damping_check_parameters.hpp"
#include "damping_check/inverse.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

using damping_check::CheckPoint;
using damping_check::CheckRequest;
using damping_check::CheckResult;

// The check's inputs (one option per row of its table, damping_check/damping_check_parameters.hpp) and what
// only the command line has: the impact speeds and --json.
struct DampingCheckOptions {
  damping_check::DampingCheckInputs inputs;
  std::string velocity_range;  // FROM:TO:N; the old form is velocity_min, velocity_max and points
  double velocity_min = 0.1, velocity_max = 10.0;
  int points = 5;
  bool old_range_given = false;  // any of --velocity-min, --velocity-max, --points
  bool json = false;
};

// The impact speeds: --velocity-range, or the old form (its defaults without either); throws InvalidInput
// naming the option the user typed.
std::vector<double> speeds_of(const DampingCheckOptions& o) {
  if (o.velocity_range.empty()) {
    try {
      return damping_check::speed_grid(o.velocity_min, o.velocity_max, o.points);
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("--velocity-min {} --velocity-max {} --points {}: {}", o.velocity_min,
                                     o.velocity_max, o.points, e.what()));
    }
  }
  if (o.old_range_given) {
    throw InvalidInput(
        "--velocity-range FROM:TO:N takes the place of --velocity-min, --velocity-max and --points: give it "
        "alone");
  }
  const RangeText range = parse_range(o.velocity_range, "--velocity-range", "impact speeds in m/s, N >= 1", 1,
                                      damping_check::kMaxSpeedPoints);
  try {
    return damping_check::speed_grid(range.from, range.to, static_cast<int>(range.count));
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--velocity-range '{}': {}", o.velocity_range, e.what()));
  }
}

CheckRequest request_of(const DampingCheckOptions& o) {
  CheckRequest r;
  r.recipe = damping_check::recipe_from_name(o.inputs.recipe);
  r.clamps = damping_check::clamps_from_name(o.inputs.clamp);
  r.reference_velocity_m_s = o.inputs.velocity_m_s;
  r.speeds_m_s = speeds_of(o);
  r.tolerance = o.inputs.tolerance;
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
    optional_field(json, "eps_at_calibration_speed", p.eps_at_calibration);
    optional_field(json, "recipe_error_at_calibration_speed", p.recipe_error_at_calibration_speed(requested));
    optional_field(json, "speed_dependence", p.speed_dependence());
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
  json.field("speed_independent", s.speed_independent()).field("clamp", o.inputs.clamp);
  json.field("reference_velocity_m_s", o.inputs.velocity_m_s);
  const auto entry = [&](std::size_t i) {
    json.field("requested_eps", eps[i])
        .field(results[i].setting.code_value_name, results[i].setting.code_value);
    json.field("zeta_reference", results[i].setting.zeta_reference);
    write_points(json, results[i], eps[i]);
  };
  if (o.inputs.map) {
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
  fmt::print("{}\n", finish_json_document(json));
}

std::string speed_text(const CheckPoint& p) {
  return p.velocity_m_s ? fmt::format("{:.6g}", *p.velocity_m_s) : "any";
}

void print_table_header() {
  fmt::print(
      "# recipe_error_at_calibration_speed = eps(v_cal) / requested - 1 (the recipe's own error where it "
      "is set up);\n# speed_dependence = eps(v) / eps(v_cal) - 1 (the law's physics away from there)\n");
  fmt::print("{:>13} {:>5} {:>10} {:>14} {:>14} {:>33} {:>16}\n", "requested_eps", "clamp", "v_m_s", "zeta",
             "actual_eps", "recipe_error_at_calibration_speed", "speed_dependence");
}

void print_row(double requested, const CheckPoint& p) {
  if (!p.actual_eps) {
    fmt::print("{:>13.10g} {:>5} {:>10} {:>14.8g}  none: overdamped, the overlap never returns to 0\n",
               requested, damping_check::clamp_name(p.clamp), speed_text(p), p.zeta);
    return;
  }
  const auto text = [](const std::optional<double>& v) {
    return v ? fmt::format("{:+.6e}", *v) : std::string("none");
  };
  fmt::print("{:>13.10g} {:>5} {:>10} {:>14.8g} {:>14.10f} {:>33} {:>16}\n", requested,
             damping_check::clamp_name(p.clamp), speed_text(p), p.zeta, *p.actual_eps,
             text(p.recipe_error_at_calibration_speed(requested)), text(p.speed_dependence()));
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
               o.inputs.velocity_m_s);
  }
  if (!o.inputs.map) {
    fmt::print("# requested eps {}: {} = {:.10g}, zeta_ref = {:.10g}\n", eps[0], s.code_value_name,
               s.code_value, s.zeta_reference);
  }
  print_table_header();
  for (std::size_t i = 0; i < eps.size(); ++i) {
    for (const CheckPoint& p : results[i].points) print_row(eps[i], p);
  }
}

// --target-eps: per clamp, the ε to request and what it then gives over the speed grid.
int run_inverse(const DampingCheckOptions& o) {
  CollisionSolver solver;
  damping_check::InverseRequest r;
  r.recipe = damping_check::recipe_from_name(o.inputs.recipe);
  r.target_eps = *o.inputs.target_eps;
  r.target_velocity_m_s = o.inputs.velocity_m_s;
  r.speeds_m_s = speeds_of(o);
  r.tolerance = o.inputs.tolerance;
  const std::vector<damping_check::InverseResult> results =
      damping_check::invert_recipe_for(r, damping_check::clamps_from_name(o.inputs.clamp), solver);
  const damping_check::RecipeSetting& s = results.front().check.setting;
  if (o.json) {
    JsonWriter json;
    json.begin_object().field("recipe", damping_check::recipe_name(s.recipe));
    json.field("source", damping_check::recipe_source(s.recipe)).field("law", law_name(s.law));
    json.field("speed_independent", s.speed_independent()).field("clamp", o.inputs.clamp);
    json.field("target_eps", r.target_eps).field("target_velocity_m_s", r.target_velocity_m_s);
    json.key("inverse").begin_array();
    for (const auto& inv : results) {
      const damping_check::RecipeSetting& setting = inv.check.setting;
      json.begin_object().field("clamp", damping_check::clamp_name(inv.check.points.front().clamp));
      json.field("eps_to_request", inv.eps_to_request).field(setting.code_value_name, setting.code_value);
      json.field("zeta_reference", setting.zeta_reference);
      write_points(json, inv.check, inv.eps_to_request);
      json.end_object();
    }
    json.end_array();
    fmt::print("{}\n", finish_json_document(json));
    return 0;
  }
  fmt::print("# recipe {}: {}\n", damping_check::recipe_name(s.recipe),
             damping_check::recipe_source(s.recipe));
  fmt::print("# inverse: the eps to request for eps = {} at {:g} m/s{}\n", r.target_eps,
             r.target_velocity_m_s,
             s.speed_independent() ? " (speed-independent: at every speed)"
                                   : " (the recipe set up there: its reference speed, YADE's vn)");
  for (const auto& inv : results) {
    fmt::print("# clamp {}: request eps {:.12g} ({} = {:.10g}, zeta_ref = {:.10g})\n",
               damping_check::clamp_name(inv.check.points.front().clamp), inv.eps_to_request,
               inv.check.setting.code_value_name, inv.check.setting.code_value,
               inv.check.setting.zeta_reference);
  }
  print_table_header();
  for (const auto& inv : results) {
    for (const CheckPoint& p : inv.check.points) print_row(inv.eps_to_request, p);
  }
  return 0;
}

int run(const DampingCheckOptions& o) {
  if (static_cast<int>(o.inputs.map) + static_cast<int>(o.inputs.eps.has_value()) +
          static_cast<int>(o.inputs.target_eps.has_value()) !=
      1) {
    throw InvalidInput(
        "give one of --eps E (one requested eps), --map (requested eps from 0.05 to 0.99) or --target-eps E "
        "(the eps to request for E at --velocity)");
  }
  if (o.inputs.target_eps) return run_inverse(o);
  const std::vector<double> eps =
      o.inputs.map ? damping_check::map_eps_grid() : std::vector<double>{*o.inputs.eps};
  CollisionSolver solver;
  const std::vector<CheckResult> results = damping_check::check_recipe_at(request_of(o), eps, solver);
  if (o.json) {
    print_json(o, eps, results);
  } else {
    print_text(o, eps, results);
  }
  return 0;
}

// The impact speeds: --velocity-range, and the old form it replaces (deprecated; returned to count its use).
std::vector<CLI::Option*> add_speed_options(CLI::App& cmd, DampingCheckOptions& o) {
  cmd.add_option("--velocity-range", o.velocity_range,
                 fmt::format("FROM:TO:N: N log-spaced impact speeds in m/s (speed-dependent recipes), ends "
                             "included, N in [1, {}] (default {:g}:{:g}:{})",
                             damping_check::kMaxSpeedPoints, o.velocity_min, o.velocity_max, o.points));
  std::vector<CLI::Option*> old_form{cmd.add_option("--velocity-min", o.velocity_min),
                                     cmd.add_option("--velocity-max", o.velocity_max),
                                     cmd.add_option("--points", o.points)};
  deprecate_old_form(old_form, "--velocity-min V1 --velocity-max V2 --points N", "--velocity-range V1:V2:N");
  return old_form;
}

}  // namespace

void add_damping_check_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<DampingCheckOptions>();
  CLI::App* cmd = app.add_subcommand(
      "damping-check",
      "the eps a DEM code's damping recipe really gives for a requested eps, clamp on and off");
  std::vector<CLI::Option*> old_form;
  add_parameter_options(*cmd, damping_check::damping_check_fields(), o->inputs,
                        [&](const damping_check::DampingCheckField& f, CLI::Option* option) {
                          if (f.word == &damping_check::DampingCheckInputs::recipe) option->required();
                          if (f.number == &damping_check::DampingCheckInputs::velocity_m_s)
                            old_form = add_speed_options(*cmd, *o);
                        });
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double)");
  cmd->callback([o, old_form, &chosen] {
    for (const CLI::Option* option : old_form) o->old_range_given = o->old_range_given || option->count() > 0;
    chosen = [o] { return run(*o); };
  });
}

}  // namespace restitution::cli
