// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_options.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <exception>
#include <string>

#include "cli/common/options.hpp"
#include "restitution/errors.hpp"
#include "restitution_gas/gas_inputs.hpp"

namespace restitution::cli {

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
                     "first Sonine coefficient a2: a number or haff (van Noije & Ernst's a2 of the Haff "
                     "eps), held constant, or evolving (a2(t) from the Sonine moment equations, from 0); "
                     "default Maxwellian (a2 = 0)");
  command
      .add_option("--collision-rate-factor", o.collision_rate_factor,
                  "factor on Enskog's collision rate (e.g. one measured on a simulation)")
      ->capture_default_str();
  command.add_option("--tolerance", o.tolerance, "accuracy of each eps solve of a law without a fast table")
      ->capture_default_str();
  command
      .add_option("--thermostat", o.thermostat,
                  "drive the gas to a steady state: langevin (LAMMPS fix langevin: --bath-temperature, "
                  "--bath-time) or white-noise (--power); default: the freely cooling gas")
      ->check(CLI::IsMember({"langevin", "white-noise"}));
  command.add_option("--bath-temperature", o.bath_temperature,
                     "Langevin bath temperature T_b in J (energy units, as --temperature; LAMMPS reads "
                     "T_b/k_B in K)");
  command.add_option("--bath-time", o.bath_time, "Langevin drag time tau_b in s (LAMMPS's damp)");
  command.add_option("--power", o.power, "white-noise driving: energy put in per sphere in W");
}

namespace {

gas::GasInputs gas_inputs(const GasOptions& o) {
  if (o.material.radius2 || o.material.mass2) {
    throw InvalidInput("--radius2 and --mass2: the gas is of one kind of sphere (monodisperse)");
  }
  gas::GasInputs in;
  in.radius_m = o.material.radius;
  in.density_kg_m3 = o.material.density;
  in.mass_kg = o.material.mass;
  in.young_modulus_pa = o.material.young_modulus;
  in.poisson_ratio = o.material.poisson_ratio;
  in.eps = o.eps;
  in.velocity_m_s = o.velocity;
  in.dissipative_constant_s = o.dissipative_constant;
  in.law = o.law;
  in.end = o.end;
  in.packing_fraction = o.packing_fraction;
  in.rms_speed_m_s = o.rms_speed;
  in.temperature_j = o.temperature;
  in.duration_s = o.duration;
  in.haff_times = o.haff_times;
  in.first_time_s = o.first_time;
  in.points_per_decade = o.points_per_decade;
  in.collision_rate_factor = o.collision_rate_factor;
  in.tolerance = o.tolerance;
  in.a2_of_haff_eps = o.a2 == "haff";
  in.a2_evolving = o.a2 == "evolving";
  if (!o.a2.empty() && !in.a2_of_haff_eps && !in.a2_evolving) {
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(o.a2, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != o.a2.size()) {
      throw InvalidInput(fmt::format("--a2 must be a number, haff or evolving, got '{}'", o.a2));
    }
    in.a2 = value;
  }
  in.thermostat = o.thermostat;
  in.bath_temperature_j = o.bath_temperature;
  in.bath_time_s = o.bath_time;
  in.power_w = o.power;
  return in;
}

}  // namespace

gas::CoolingRequest cooling_request(const GasOptions& o) {
  return gas::cooling_request(gas_inputs(o), gas::ArgumentStyle::option);
}

std::optional<gas::Thermostat> thermostat_of(const GasOptions& o) {
  return gas::thermostat_of(gas_inputs(o), gas::ArgumentStyle::option);
}

}  // namespace restitution::cli
