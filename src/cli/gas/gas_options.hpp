// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The options of `restitution gas` (docs/cli.md, docs/gas.md): the spheres and their law as `dem` takes them
// (the material options, --eps with --velocity or --dissipative-constant, --law, --end), the gas
// (--packing-fraction, --rms-speed or --temperature) and the span of time (--duration or --haff-times). Held
// in one struct so that further modes of the command add their options beside these.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/common/material_options.hpp"
#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"

namespace restitution::cli {

struct GasOptions {
  MaterialOptions material;  // --radius and --density or --mass; Y and ν with --dissipative-constant
  std::optional<double> eps, velocity, dissipative_constant;
  std::string law = law_name(LawKind::viscoelastic_hertz);
  std::string end = end_name(CollisionEnd::delayed_recovery);
  std::optional<double> packing_fraction;
  std::optional<double> rms_speed, temperature;  // m/s per direction, or J
  std::optional<double> duration, haff_times;    // s, or Haff times τ₀
  double first_time = 0.0;                       // s; 0: six decades below the duration
  int points_per_decade = gas::CoolingRequest{}.points_per_decade;
  std::string a2;  // empty: Maxwellian; a number, or "haff" (van Noije & Ernst's a₂ of the Haff ε)
  double collision_rate_factor = 1.0;
  double tolerance = SolveOptions{}.tolerance;
  std::string thermostat;  // empty: freely cooling; langevin or white-noise (the driven gas)
  std::optional<double> bath_temperature, bath_time, power;  // J, s; W per sphere
};

void add_gas_options(CLI::App& command, GasOptions& o);
// The request the options describe; throws InvalidInput naming the option that is missing, extra or bad.
gas::CoolingRequest cooling_request(const GasOptions& o);
// The thermostat of --thermostat (none: the freely cooling gas); throws InvalidInput naming the option.
std::optional<gas::Thermostat> thermostat_of(const GasOptions& o);

}  // namespace restitution::cli
