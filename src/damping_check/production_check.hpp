// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a production run with the law's lines needs to know (docs/dem.md, "Production runs"): the contact
// duration at each listed speed, the ε error the code's velocity-Verlet makes at a time step
// (dem/integrator_eps.hpp), the largest time step that keeps that error within a bound, and the constant-ε
// companion lines (damping_check/constant_eps_lines.hpp). `restitution dem --timestep`, `--max-eps-error` and
// `--constant-eps` word it.
#include <optional>
#include <vector>

#include "damping_check/constant_eps_lines.hpp"
#include "dem/integrator_eps.hpp"
#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::damping_check {

struct ProductionRequest {
  std::optional<double> time_step_s;    // the production run's dt [s]: its ε error per speed
  std::optional<double> max_eps_error;  // the bound on |ε error|: the largest dt per speed and overall
  bool constant_eps = false;            // the constant-ε companion lines
  double tolerance = SolveOptions{}.tolerance;
};

struct ProductionCheck {
  std::vector<double> contact_duration_s;         // per speed of the lines' result, at its end
  std::vector<dem::IntegratorError> errors;       // per speed, with time_step_s
  std::vector<double> largest_time_step_s;        // per speed, with max_eps_error
  std::optional<double> largest_time_step_all_s;  // the smallest of those: dt for every listed speed
  std::optional<ConstantEpsLines> constant_eps;
};

// For the lines `r` (dem::check_lines) of `material`. InvalidInput naming --timestep and --max-eps-error when
// a time step or a bound is asked of a code whose integrator is not LAMMPS's velocity-Verlet (LAMMPS and
// LIGGGHTS are), and naming --constant-eps for another code than LAMMPS.
ProductionCheck check_production(const dem::LinesResult& r, const Material& material,
                                 const ProductionRequest& request);

}  // namespace restitution::damping_check
