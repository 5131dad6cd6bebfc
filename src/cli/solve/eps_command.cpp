// SPDX-License-Identifier: BSD-3-Clause
// `restitution eps`: one collision, ε at the requested end(s), as a table or as one JSON object.
#include <fmt/core.h>

#include <memory>
#include <optional>
#include <string_view>

#include "cli/common/adhesion_options.hpp"
#include "cli/common/build_json.hpp"
#include "cli/common/commands.hpp"
#include "cli/common/head_on_options.hpp"
#include "cli/common/json_writer.hpp"
#include "cli/common/options.hpp"
#include "cli/common/result_json.hpp"
#include "cli/solve/eps_adhesion.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"

namespace restitution::cli {
namespace {

struct EpsOptions {
  std::optional<double> zeta, beta, velocity, damping_ratio;
  HeadOnInputs inputs;  // the law, end, tolerance, method and material (restitution/head_on_parameters.hpp)
  bool json = false;
  AdhesionOptions adhesion;  // with the material and A below: an adhesive collision
  std::optional<double> dissipative_constant;
};

ContactLaw law_from(const EpsOptions& o) {
  LawKind kind{};
  try {
    kind = law_from_name(o.inputs.law);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--law: {}", e.what()));
  }
  // A law labelled by another parameter than ζ (the dash-pot's damping ratio) also takes it by name.
  const char* parameter = law_parameter(kind).name;
  const bool takes_ratio = std::string_view(parameter) == "damping-ratio";
  if (!has_dissipative_constant(kind) && (o.beta || o.velocity)) {
    throw InvalidInput(
        fmt::format("--beta and --velocity belong to --law viscoelastic-hertz; --law {} takes {}",
                    o.inputs.law, takes_ratio ? "--damping-ratio or --zeta" : "--zeta"));
  }
  if (o.damping_ratio && !takes_ratio) {
    throw InvalidInput(
        fmt::format("--damping-ratio belongs to --law linear-dashpot; --law {} takes --zeta", o.inputs.law));
  }
  if (o.damping_ratio) {
    if (o.zeta) throw InvalidInput("give either --zeta or --damping-ratio, not both");
    return ContactLaw::of_parameter(kind, *o.damping_ratio);
  }
  if (takes_ratio && !o.zeta) {
    throw InvalidInput(fmt::format("--law {} needs --damping-ratio (or --zeta = 2 r)", o.inputs.law));
  }
  if (o.zeta) {
    if (o.beta || o.velocity) throw InvalidInput("give either --zeta or --beta with --velocity, not both");
    require_checked_zeta(*o.zeta);
    return ContactLaw::natural(kind, *o.zeta + 0.0);  // + 0.0: -0 is printed as 0
  }
  if (o.beta && o.velocity) {
    const ContactLaw law = ContactLaw::hertz_scaled(*o.beta, *o.velocity);
    require_checked_zeta(law.parameter());
    return law;
  }
  if (o.beta || o.velocity) throw InvalidInput("--beta and --velocity go together");
  throw InvalidInput("give --zeta, or --beta with --velocity");
}

void print_table(const CollisionResult& r) {
  fmt::print("{} collision, {} = {}, tolerance {:g} (relative to min(eps, 1-eps)), method {}\n",
             law_name(r.law), law_parameter(r.law).name, r.parameter, r.tolerance, method_name(r.method));
  if (r.speed_independent) fmt::print("eps does not depend on the impact speed for this law\n");
  fmt::print("times and lengths in natural units (x'(0) = 1)\n");
  fmt::print("  maximal compression   tau = {:.12g}   x = {:.12g}\n", r.max_compression.tau,
             r.max_compression.x);
  fmt::print("  {:<18} {:>22} {:>22} {:>20} {:>20}\n", "end", "eps", "1 - eps", "tau_c", "x_end");
  auto row = [](const char* name, const EndResult& e) {
    fmt::print("  {:<18} {:>22.15g} {:>22.15g} {:>20.12g} {:>20.12g}\n", name, e.eps, e.one_minus_eps, e.tau,
               e.x);
  };
  for (const CollisionEnd end : kCollisionEnds) {
    if (r[end]) row(end_name(end), *r[end]);
  }
  fmt::print("  solver: {} steps, {} right-hand sides, {} Jacobians, {} root functions\n", r.stats.steps,
             r.stats.rhs_evaluations, r.stats.jacobian_evaluations, r.stats.root_evaluations);
}

int run_eps(const EpsOptions& o) {
  const ContactLaw law = law_from(o);
  CollisionSolver solver;
  const CollisionResult result = solver.solve(law, solve_options_of(o.inputs));
  if (o.json) {
    JsonWriter json;
    json.begin_object();
    write_collision_fields(json, result);
    fmt::print("{}\n", finish_json_document(json));
  } else {
    print_table(result);
  }
  return 0;
}

}  // namespace

void add_eps_command(CLI::App& app, Action& chosen) {
  auto o = std::make_shared<EpsOptions>();
  CLI::App* cmd = app.add_subcommand("eps", "coefficient of restitution of one collision");
  cmd->add_option(
      "--zeta", o->zeta,
      "zeta >= 0 of the natural form x'' + zeta x^b x' + x^a = 0 (viscoelastic Hertz: zeta = beta "
      "v^{1/5}; linear dash-pot: zeta = 2 r)");
  cmd->add_option("--beta", o->beta,
                  "beta >= 0 in s^{1/5} m^{-1/5} (with --velocity: the 2008 paper's Eq. 23)");
  cmd->add_option("--velocity", o->velocity,
                  "impact speed v > 0 (scaled as in the 2008 paper's Eq. 23; with --adhesion in m/s)");
  add_head_on_options(*cmd, o->inputs, {"law"});
  cmd->add_option("--damping-ratio", o->damping_ratio,
                  "damping ratio r >= 0 of the linear dash-pot x'' + 2r x' + x = 0");
  add_head_on_options(*cmd, o->inputs, {"end", "tolerance", "method"});
  cmd->add_flag("--json", o->json,
                "print one JSON object (numbers in the shortest form that reads back to the same double); "
                "the tolerance holds for eps when eps is small "
                "and for one_minus_eps when eps is near 1");
  add_adhesion_options(*cmd, o->adhesion);
  cmd->add_option("--dissipative-constant", o->dissipative_constant,
                  "with --adhesion: dissipative constant A in s (default 0: elastic); jkr-lammps and dmt use "
                  "LAMMPS's damp = 2 A E*/m_eff");
  add_head_on_material_options(*cmd, o->inputs);
  cmd->callback([o, cmd, &chosen] {
    if (!o->adhesion.any() && !o->dissipative_constant && !o->inputs.any_material()) {
      chosen = [o] { return run_eps(*o); };
      return;
    }
    // An adhesive collision is given by its material and speed, not by the natural form's parameters.
    std::string conflict;
    for (const char* option : {"--zeta", "--beta", "--damping-ratio", "--law", "--end", "--method"}) {
      if (conflict.empty() && cmd->count(option) > 0) conflict = option;
    }
    chosen = [o, conflict] {
      if (!conflict.empty()) {
        throw InvalidInput(
            fmt::format("{} does not go with --adhesion (nor with the material options): an "
                        "adhesive collision takes the material, --surface-energy and --velocity",
                        conflict));
      }
      if (!o->adhesion.model) {
        throw InvalidInput(
            "--surface-energy, --dissipative-constant and the material options belong to --adhesion");
      }
      const AdhesiveContact contact = adhesive_contact_from(
          adhesive_model_from_name(*o->adhesion.model), o->adhesion,
          material_from(material_options_of(o->inputs)), o->dissipative_constant.value_or(0.0));
      return run_adhesive_eps(contact, o->velocity, o->inputs.tolerance, o->json);
    };
  });
}

}  // namespace restitution::cli
