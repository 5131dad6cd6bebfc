// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_gas/gas_parameters.hpp"

#include <fmt/format.h>

#include <utility>

#include "restitution/contact_law.hpp"
#include "restitution/errors.hpp"
#include "restitution/parameter_rows.hpp"
#include "restitution/solve_types.hpp"

// A row leaves out what it does not use. GCC 12 crashes on defaults of class type in a class template
// (ParameterField's words and range), so those have none and -Wextra would name each row that leaves them
// out.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace restitution::gas {
namespace {

using K = FieldKind;
const FieldRange kPositive{.text = "a value > 0"};

void check_thermostat(const std::string& word) {
  if (word != "langevin" && word != "white-noise") {
    throw InvalidInput(R"("langevin" (bath_temperature in J, bath_time in s) or "white-noise" (power in W))");
  }
}

// The spheres and their law: the rows of the material options and of --eps, --law and --end.
std::vector<GasField> sphere_and_law_fields() {
  using In = GasInputs;
  std::vector<GasField> fields;
  for (const auto& [name, member] :
       {std::pair{"young_modulus", &In::young_modulus_pa}, std::pair{"poisson_ratio", &In::poisson_ratio},
        std::pair{"radius", &In::radius_m}, std::pair{"density", &In::density_kg_m3},
        std::pair{"mass", &In::mass_kg}}) {
    fields.push_back(material_field(name, member));
  }
  std::vector<GasField> rest = {
      {.name = "eps",
       .kind = K::optional_number,
       .unit = "",
       .help = "coefficient of restitution in (0, 1) at --velocity: calibrates the law",
       .optional_number = &In::eps,
       .range = FieldRange{.low = 0.0, .high = 1.0, .text = "a value in (0, 1)"}},
      {.name = "velocity",
       .kind = K::optional_number,
       .unit = "m/s",
       .help = "impact speed in m/s at which --eps holds",
       .optional_number = &In::velocity_m_s,
       .range = kPositive},
      {.name = "dissipative_constant",
       .kind = K::optional_number,
       .unit = "s",
       .help =
           "instead of --eps: the dissipative constant A in s (viscoelastic Hertz; needs --young-modulus and "
           "--poisson-ratio)",
       .optional_number = &In::dissipative_constant_s,
       .from_material = true},
      law_field(&In::law),
      end_field(&In::end),
  };
  fields.insert(fields.end(), rest.begin(), rest.end());
  return fields;
}

// The gas, its span of time, the theory's settings and the thermostat.
std::vector<GasField> gas_and_time_fields() {
  using In = GasInputs;
  return {
      {.name = "packing_fraction",
       .kind = K::optional_number,
       .unit = "",
       .help = "packing fraction phi of the gas in (0, 0.5) (Enskog factor of Carnahan-Starling)",
       .optional_number = &In::packing_fraction,
       .range = FieldRange{.low = 0.0, .high = 0.5, .text = "a value in (0, 0.5)"},
       .required = "the packing fraction in (0, 0.5)"},
      {.name = "rms_speed",
       .kind = K::optional_number,
       .unit = "m/s",
       .help = "initial rms speed per direction in m/s (T0 = m v^2), or --temperature",
       .optional_number = &In::rms_speed_m_s,
       .range = kPositive},
      {.name = "temperature",
       .kind = K::optional_number,
       .unit = "J",
       .help = "initial granular temperature T0 = m<v^2>/3 in J",
       .optional_number = &In::temperature_j,
       .range = kPositive},
      {.name = "duration",
       .kind = K::optional_number,
       .unit = "s",
       .help = "span of time in s, or --haff-times",
       .optional_number = &In::duration_s,
       .range = kPositive},
      {.name = "haff_times",
       .kind = K::optional_number,
       .unit = "",
       .help = "span of time in Haff times tau0",
       .optional_number = &In::haff_times,
       .range = kPositive},
      {.name = "first_time",
       .kind = K::number,
       .unit = "s",
       .help = "first time of the log-spaced grid in s (default: six decades below the end)",
       .number = &In::first_time_s,
       .range = FieldRange{.low_open = false, .text = "a time >= 0 s (0: six decades below the end)"}},
      {.name = "points_per_decade",
       .kind = K::whole_number,
       .unit = "",
       .help = "points of the time grid per decade",
       .whole_number = &In::points_per_decade,
       .range = FieldRange{.low = 1.0,
                           .low_open = false,
                           .high = 1000.0,
                           .high_open = false,
                           .text = "a whole number in [1, 1000]"},
       .show_default = true},
      {.name = "a2",
       .kind = K::number_or_word,
       .unit = "",
       .help = "first Sonine coefficient a2: a number or haff (van Noije & Ernst's a2 of the Haff eps), held "
               "constant, or evolving (a2(t) from the Sonine moment equations, from 0); default Maxwellian "
               "(a2 = 0)",
       .words = {"haff", "evolving"}},
      {.name = "collision_rate_factor",
       .kind = K::number,
       .unit = "",
       .help = "factor on Enskog's collision rate (e.g. one measured on a simulation)",
       .number = &In::collision_rate_factor,
       .range = kPositive,
       .show_default = true},
      {.name = "tolerance",
       .kind = K::number,
       .unit = "",
       .help = "accuracy of each eps solve of a law without a fast table",
       .number = &In::tolerance,
       .show_default = true},
      {.name = "thermostat",
       .kind = K::optional_word,
       .unit = "",
       .help = "drive the gas to a steady state: langevin (LAMMPS fix langevin: --bath-temperature, "
               "--bath-time) or white-noise (--power); default: the freely cooling gas",
       .word = &In::thermostat,
       .words = {"langevin", "white-noise"},
       .check_word = check_thermostat},
      {.name = "bath_temperature",
       .kind = K::optional_number,
       .unit = "J",
       .help =
           "Langevin bath temperature T_b in J (energy units, as --temperature; LAMMPS reads T_b/k_B in K)",
       .optional_number = &In::bath_temperature_j,
       .range = kPositive},
      {.name = "bath_time",
       .kind = K::optional_number,
       .unit = "s",
       .help = "Langevin drag time tau_b in s (LAMMPS's damp)",
       .optional_number = &In::bath_time_s,
       .range = kPositive},
      {.name = "power",
       .kind = K::optional_number,
       .unit = "W",
       .help = "white-noise driving: energy put in per sphere in W",
       .optional_number = &In::power_w,
       .range = kPositive},
  };
}

}  // namespace

const std::vector<GasField>& gas_fields() {
  static const std::vector<GasField> fields = [] {
    std::vector<GasField> all = sphere_and_law_fields();
    std::vector<GasField> rest = gas_and_time_fields();
    all.insert(all.end(), rest.begin(), rest.end());
    return all;
  }();
  return fields;
}

const std::vector<FieldGroup>& gas_field_groups() {
  static const std::vector<FieldGroup> groups{
      {"eps", "velocity", FieldGroup::together,
       "eps and velocity go together (the impact speed eps holds at, m/s)"},
      {"rms_speed", "temperature", FieldGroup::exactly_one,
       "give exactly one of rms_speed (m/s per direction) and temperature (J)"},
      {"duration", "haff_times", FieldGroup::exactly_one, "give exactly one of duration (s) and haff_times"},
  };
  return groups;
}

const GasField& gas_field(std::string_view name) {
  return field_named(gas_fields(), name, "gas");
}

void set_sonine_word(GasInputs& inputs, std::string_view word) {
  inputs.a2_of_haff_eps = word == "haff";
  inputs.a2_evolving = word == "evolving";
}

}  // namespace restitution::gas
