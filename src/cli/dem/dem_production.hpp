// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem` for production runs (docs/dem.md, "Production runs"): the options and the words of
// damping_check/production_check.hpp (the contact duration at each listed speed, with --timestep DT the ε
// error the code's integrator makes at that dt, with --max-eps-error the largest dt that keeps it within the
// bound, and with --constant-eps the constant-ε companion lines).
#include <CLI/CLI.hpp>

#include <optional>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "damping_check/production_check.hpp"
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

using Production = damping_check::ProductionCheck;
// damping_check::check_production for these options.
Production production(const dem::LinesResult& r, const Material& material, const ProductionOptions& o,
                      double tolerance);

void print_production_text(const dem::LinesResult& r, const Production& p, const ProductionOptions& o);
void write_production_json(JsonWriter& json, const dem::LinesResult& r, const Production& p,
                           const ProductionOptions& o);

}  // namespace restitution::cli
