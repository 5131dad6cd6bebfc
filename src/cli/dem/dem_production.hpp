// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem` for production runs (docs/dem.md, "Production runs"): the contact duration at each listed
// speed, with --timestep DT the ε error the code's integrator makes at that dt (dem/integrator_eps.hpp), with
// --max-eps-error the largest dt that keeps it within the bound, and with --constant-eps the constant-ε
// companion lines (damping_check/constant_eps_lines.hpp).
#include <CLI/CLI.hpp>

#include <optional>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "damping_check/constant_eps_lines.hpp"
#include "dem/integrator_eps.hpp"
#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::cli {

struct ProductionOptions {
  std::optional<double> timestep;       // --timestep [s]
  std::optional<double> max_eps_error;  // --max-eps-error
  bool constant_eps = false;            // --constant-eps
};
void add_production_options(CLI::App& cmd, ProductionOptions& o);
// Whether any of the options was given (the several-types path refuses them).
bool any_production_option(const ProductionOptions& o);

struct Production {
  std::vector<double> contact_duration_s;    // per speed of the lines' result
  std::vector<dem::IntegratorError> errors;  // per speed, with --timestep
  std::vector<double> largest_time_step_s;   // per speed, with --max-eps-error
  std::optional<damping_check::ConstantEpsLines> constant_eps;
};
// InvalidInput naming the option when --timestep or --max-eps-error is given for a code whose integrator is
// not LAMMPS's velocity-Verlet (LAMMPS and LIGGGHTS are), or --constant-eps for another code than LAMMPS.
Production production(const dem::LinesResult& r, const Material& material, const ProductionOptions& o,
                      double tolerance);

void print_production_text(const dem::LinesResult& r, const Production& p, const ProductionOptions& o);
void write_production_json(JsonWriter& json, const dem::LinesResult& r, const Production& p,
                           const ProductionOptions& o);

}  // namespace restitution::cli
