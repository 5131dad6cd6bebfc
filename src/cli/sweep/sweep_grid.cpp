// SPDX-License-Identifier: BSD-3-Clause
#include "cli/sweep/sweep_grid.hpp"

#include <fmt/core.h>

#include <cmath>
#include <utility>

#include "cli/common/range_option.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/sweep.hpp"
#include "restitution/units.hpp"
#include "sweep/velocity_sweep.hpp"

namespace restitution::cli {
namespace {

bool physical_form(const SweepOptions& o) {
  return o.stiffness || o.damping_coefficient || o.effective_mass;
}

bool velocity_form(const SweepOptions& o) {
  return o.velocity_min || o.velocity_max || o.beta || o.dissipative_constant || o.inputs.any_material() ||
         physical_form(o);
}

// ContactLaw::physical's coefficients: all three, and nothing of the Hertz forms beside them.
PhysicalCoefficients physical_coefficients(const SweepOptions& o) {
  if (o.beta || o.dissipative_constant || o.inputs.any_material()) {
    throw InvalidInput(
        "--stiffness, --damping-coefficient and --effective-mass replace --beta and a material: give one "
        "form");
  }
  if (!o.stiffness || !o.damping_coefficient || !o.effective_mass) {
    throw InvalidInput(
        "a sweep in physical units needs --stiffness, --damping-coefficient and --effective-mass together");
  }
  return {*o.stiffness, *o.damping_coefficient, *o.effective_mass};
}

// β (and k for a material) or the physical coefficients of the ε(v) forms; throws InvalidInput naming what is
// missing or mixed.
VelocitySubject velocity_subject(const SweepOptions& o, LawKind law) {
  if (o.zeta_min || o.zeta_max) {
    throw InvalidInput("give --zeta-range, or --velocity-range with --beta or a material, not both");
  }
  if (!o.velocity_min || !o.velocity_max) {
    throw InvalidInput(
        fmt::format("an impact-speed sweep needs --velocity-min and --velocity-max (m/s): --{} is required",
                    o.velocity_min ? "velocity-max" : "velocity-min"));
  }
  if (physical_form(o)) return {std::nullopt, std::nullopt, physical_coefficients(o)};
  const bool material = o.inputs.any_material() || o.dissipative_constant;
  if (!has_dissipative_constant(law)) {
    throw InvalidInput(fmt::format(
        "--beta and a material describe --law viscoelastic-hertz; --law {} sweeps impact speeds with "
        "--stiffness, --damping-coefficient and --effective-mass (ContactLaw::physical)",
        law_name(law)));
  }
  if (o.beta.has_value() == material) {
    throw InvalidInput(
        "an impact-speed sweep needs exactly one of --beta and a material (--young-modulus, "
        "--poisson-ratio, --radius, --density or --mass, --dissipative-constant), or the physical "
        "coefficients --stiffness, --damping-coefficient and --effective-mass");
  }
  if (o.beta) {
    if (!std::isfinite(*o.beta) || *o.beta < 0.0) {
      throw InvalidInput(
          fmt::format("--beta must be a finite number >= 0 (s^(1/5) m^(-1/5)), got {}", *o.beta));
    }
    return {*o.beta, std::nullopt, std::nullopt};
  }
  Material m = material_from(material_options_of(o.inputs));
  if (!o.dissipative_constant) {
    throw InvalidInput(
        "a material sweep needs --dissipative-constant (A in s; `restitution calibrate` computes it from a "
        "measured eps)");
  }
  m.dissipative_constant_s = *o.dissipative_constant;
  const MaterialConstants c = material_constants(m);
  return {c.hertz.beta, c.hertz.k, std::nullopt};
}

// --VARIABLE-range FROM:TO:N (when given) read into the old form's --VARIABLE-min, --VARIABLE-max and
// --points, which must not be given beside it.
void read_range(const std::string& text, const std::string& variable, const std::string& what,
                std::optional<double>& min, std::optional<double>& max, long long& points) {
  if (text.empty()) return;
  if (min || max || points != 0) {
    throw InvalidInput(
        fmt::format("--{0}-range FROM:TO:N takes the place of --{0}-min, --{0}-max and --points: "
                    "give it alone",
                    variable));
  }
  const RangeText range = parse_range(text, fmt::format("--{}-range", variable), what, 1,
                                      static_cast<long long>(kMaxSweepPoints));
  min = range.from;
  max = range.to;
  points = range.count;
}

}  // namespace

SweepOptions with_ranges(SweepOptions o) {
  if (!o.zeta_range.empty() && !o.velocity_range.empty()) {
    throw InvalidInput("give --zeta-range or --velocity-range, not both");
  }
  read_range(o.zeta_range, "zeta", "zeta, N >= 1 points", o.zeta_min, o.zeta_max, o.points);
  read_range(o.velocity_range, "velocity", "impact speeds in m/s, N >= 1", o.velocity_min, o.velocity_max,
             o.points);
  return o;
}

SweepGrid sweep_grid(const SweepOptions& o) {
  if (!velocity_form(o) && !o.zeta_min && !o.zeta_max) {
    throw InvalidInput(
        "give --zeta-range FROM:TO:N, or --velocity-range FROM:TO:N with --beta or a material");
  }
  if (o.points == 0) {
    throw InvalidInput(fmt::format("--points is required with {}", velocity_form(o)
                                                                       ? "--velocity-min/--velocity-max"
                                                                       : "--zeta-min and --zeta-max"));
  }
  // Signed on the command line so that a negative count is reported as such, not wrapped around.
  if (o.points < 1) throw InvalidInput(fmt::format("--points must be >= 1, got {}", o.points));
  const auto points = static_cast<std::size_t>(o.points);
  SweepGrid grid;
  try {
    grid.law = law_from_name(o.inputs.law);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--law: {}", e.what()));
  }
  if (!velocity_form(o)) {
    if (!o.zeta_min || !o.zeta_max) {
      throw InvalidInput(fmt::format("--{} is required with --{}", o.zeta_min ? "zeta-max" : "zeta-min",
                                     o.zeta_min ? "zeta-min" : "zeta-max"));
    }
    try {
      grid.zetas = zeta_values({*o.zeta_min, *o.zeta_max, points, o.log});
    } catch (const InvalidInput& e) {
      if (o.zeta_range.empty()) throw;
      throw InvalidInput(fmt::format("--zeta-range '{}': {}", o.zeta_range, e.what()));
    }
    return grid;
  }
  const VelocitySubject subject = velocity_subject(o, grid.law);
  // The speeds and their ζ: a bad end or a speed outside the checked range is named by the option typed.
  try {
    VelocitySweep sweep = velocity_sweep(
        grid.law, subject, zeta_values({*o.velocity_min, *o.velocity_max, points, o.log, "velocity"}));
    grid.zetas = std::move(sweep.zetas);
    grid.velocity = std::move(sweep.columns);
  } catch (const InvalidInput& e) {
    if (o.velocity_range.empty()) throw;
    throw InvalidInput(fmt::format("--velocity-range '{}': {}", o.velocity_range, e.what()));
  }
  return grid;
}

}  // namespace restitution::cli
