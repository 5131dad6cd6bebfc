// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_options.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <cmath>

#include "cli/common/options.hpp"
#include "gas/collision_integral.hpp"
#include "restitution/errors.hpp"
#include "restitution/material.hpp"
#include "restitution/units.hpp"

namespace restitution::cli {
namespace {

// Exactly one of two options.
template <class T>
const T& one_of(const std::optional<T>& a, const char* a_name, const std::optional<T>& b,
                const char* b_name) {
  if (a.has_value() == b.has_value()) {
    throw InvalidInput(fmt::format("give exactly one of {} and {}", a_name, b_name));
  }
  return a ? *a : *b;
}

void require_positive(const std::optional<double>& value, const char* option, const char* unit) {
  if (value && !(std::isfinite(*value) && *value > 0.0)) {
    throw InvalidInput(fmt::format("{} must be finite and > 0{}, got {}", option, unit, *value));
  }
}

// Mass [kg] and diameter [m] of the gas's spheres: --radius with --mass or --density.
gas::GasParticles particles_of(const GasOptions& o) {
  if (o.material.radius2 || o.material.mass2) {
    throw InvalidInput("--radius2 and --mass2: the gas is of one kind of sphere (monodisperse)");
  }
  if (!o.material.radius) throw InvalidInput("the gas needs --radius (and --density or --mass)");
  require_positive(o.material.radius, "--radius", " m");
  require_positive(o.material.density, "--density", " kg/m^3");
  require_positive(o.material.mass, "--mass", " kg");
  gas::GasParticles p;
  p.diameter_m = 2.0 * *o.material.radius;
  (void)one_of(o.material.mass, "--mass", o.material.density, "--density");
  p.mass_kg = o.material.mass ? *o.material.mass : sphere_mass_kg(*o.material.radius, *o.material.density);
  if (!o.packing_fraction) throw InvalidInput("the gas needs --packing-fraction");
  if (!(*o.packing_fraction > 0.0 && *o.packing_fraction < 0.5)) {
    throw InvalidInput(fmt::format("--packing-fraction must be in (0, 0.5) (a homogeneous fluid), got {}",
                                   *o.packing_fraction));
  }
  p.packing_fraction = *o.packing_fraction;
  return p;
}

gas::ImpactLaw law_of(const GasOptions& o) {
  LawKind kind = LawKind::viscoelastic_hertz;
  try {
    kind = law_from_name(o.law);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("--law: {}", e.what()));
  }
  const CollisionEnd end = end_from_name(o.end);
  if (o.dissipative_constant) {
    if (o.eps || o.velocity) throw InvalidInput("--dissipative-constant excludes --eps and --velocity");
    if (!has_dissipative_constant(kind)) {
      throw InvalidInput(
          fmt::format("--dissipative-constant belongs to --law viscoelastic-hertz; --law {} takes --eps and "
                      "--velocity",
                      o.law));
    }
    Material m = material_from(o.material);
    m.dissipative_constant_s = *o.dissipative_constant;
    return gas::hertz_impact_law(material_constants(m).hertz.beta, end);
  }
  if (!o.eps || !o.velocity) {
    throw InvalidInput(
        "the law needs --eps with --velocity (the impact speed in m/s it was measured at), or "
        "--dissipative-constant with the material");
  }
  return gas::impact_law_from_eps(kind, *o.eps, *o.velocity, end, o.tolerance);
}

}  // namespace

void add_gas_options(CLI::App& command, GasOptions& o) {
  add_material_options(command, o.material);
  command.add_option("--eps", o.eps,
                     "coefficient of restitution in (0, 1) at --velocity: calibrates the law");
  command.add_option("--velocity", o.velocity, "impact speed in m/s at which --eps holds");
  command.add_option("--dissipative-constant", o.dissipative_constant,
                     "instead of --eps: the dissipative constant A in s (viscoelastic Hertz; needs "
                     "--young-modulus and --poisson-ratio)");
  add_law_option(command, o.law);
  command
      .add_option("--end", o.end,
                  "end of the collision: naive (no clamp) or delayed-recovery (force clamped)")
      ->check(CLI::IsMember(end_names()))
      ->capture_default_str();
  command.add_option("--packing-fraction", o.packing_fraction,
                     "packing fraction phi of the gas in (0, 0.5) (Enskog factor of Carnahan-Starling)");
  command.add_option("--rms-speed", o.rms_speed,
                     "initial rms speed per direction in m/s (T0 = m v^2), or --temperature");
  command.add_option("--temperature", o.temperature, "initial granular temperature T0 = m<v^2>/3 in J");
  command.add_option("--duration", o.duration, "span of time in s, or --haff-times");
  command.add_option("--haff-times", o.haff_times, "span of time in Haff times tau0");
  command.add_option("--first-time", o.first_time,
                     "first time of the log-spaced grid in s (default: six decades below the end)");
  command.add_option("--points-per-decade", o.points_per_decade, "points of the time grid per decade")
      ->capture_default_str();
  command.add_option("--a2", o.a2,
                     "first Sonine coefficient a2, held constant: a number, or haff (van Noije & Ernst's a2 "
                     "of the Haff eps); default Maxwellian (a2 = 0)");
  command
      .add_option("--collision-rate-factor", o.collision_rate_factor,
                  "factor on Enskog's collision rate (e.g. one measured on a simulation)")
      ->capture_default_str();
  command.add_option("--tolerance", o.tolerance, "accuracy of each eps solve of a law without a fast table")
      ->capture_default_str();
}

gas::CoolingRequest cooling_request(const GasOptions& o) {
  gas::CoolingRequest r;
  r.particles = particles_of(o);
  r.law = law_of(o);
  const double speed_or_temperature = one_of(o.rms_speed, "--rms-speed", o.temperature, "--temperature");
  r.initial_temperature_j =
      o.rms_speed ? r.particles.mass_kg * speed_or_temperature * speed_or_temperature : speed_or_temperature;
  require_positive(o.rms_speed, "--rms-speed", " m/s");
  require_positive(o.temperature, "--temperature", " J");
  require_positive(o.duration, "--duration", " s");
  require_positive(o.haff_times, "--haff-times", "");
  r.duration = one_of(o.duration, "--duration", o.haff_times, "--haff-times");
  r.duration_in_haff_times = o.haff_times.has_value();
  r.first_time_s = o.first_time;
  r.points_per_decade = o.points_per_decade;
  r.collision_rate_factor = o.collision_rate_factor;
  r.tolerance = o.tolerance;
  if (o.a2 == "haff") {
    r.a2 = gas::sonine_a2_constant_eps(gas::haff_reference(r).eps);  // the Maxwellian gas's Haff ε
  } else if (!o.a2.empty()) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(o.a2, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != o.a2.size()) throw InvalidInput(fmt::format("--a2 must be a number or haff, got '{}'", o.a2));
    r.a2 = value;
  }
  return r;
}

}  // namespace restitution::cli
