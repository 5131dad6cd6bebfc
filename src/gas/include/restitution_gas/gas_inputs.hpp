// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The gas as a front end gives it (the command `restitution gas`, a scene's [[gas]] section, Python's
// restitution.gas): the spheres, their law as the material or ε at a speed, the gas and the span of time,
// each optional, turned into a CoolingRequest by one set of rules whose errors name the argument in the
// caller's spelling (--packing-fraction on the command line, packing_fraction in Python). Also the curve's
// columns in the order the CSV and the JSON give them.
#include <optional>
#include <string>
#include <vector>

#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"

namespace restitution::gas {

struct GasInputs {
  std::optional<double> radius_m, density_kg_m3, mass_kg;  // radius with density or mass
  std::optional<double> young_modulus_pa, poisson_ratio;   // with dissipative_constant_s
  std::optional<double> eps, velocity_m_s, dissipative_constant_s;
  std::string law = "viscoelastic-hertz";  // a law name (restitution/contact_law.hpp)
  std::string end = "delayed-recovery";    // an end name
  std::optional<double> packing_fraction;
  std::optional<double> rms_speed_m_s, temperature_j;  // per direction, or T0
  std::optional<double> duration_s, haff_times;        // s, or Haff times τ₀
  double first_time_s = 0.0;                           // 0: six decades below the end
  int points_per_decade = CoolingRequest{}.points_per_decade;
  std::optional<double> a2;     // none: Maxwellian, unless a2_of_haff_eps
  bool a2_of_haff_eps = false;  // van Noije & Ernst's a₂ of the Maxwellian gas's Haff ε
  bool a2_evolving = false;     // a₂(t) from the Sonine moment equations, from 0 (a Maxwellian start)
  double collision_rate_factor = 1.0;
  double tolerance = SolveOptions{}.tolerance;
  // The driven gas (driven.hpp): empty for the freely cooling gas, or "langevin" (bath_temperature_j [J],
  // bath_time_s [s]) or "white-noise" (power_w [W] per sphere).
  std::string thermostat;
  std::optional<double> bath_temperature_j, bath_time_s, power_w;
};

// How errors spell an argument: "--packing-fraction" (option) or "packing_fraction" (keyword).
enum class ArgumentStyle { option, keyword };

// The request the inputs describe; throws InvalidInput naming the argument that is missing, extra or bad.
CoolingRequest cooling_request(const GasInputs& inputs, ArgumentStyle style);

// The thermostat the inputs name, none for the freely cooling gas; throws InvalidInput naming the argument
// that is missing, extra or bad (bath_temperature and bath_time for langevin, power for white-noise).
std::optional<Thermostat> thermostat_of(const GasInputs& inputs, ArgumentStyle style);

// One column of the curve: its name (the CSV header, the JSON key) and its values.
struct CurveColumn {
  const char* name;
  const std::vector<double>* values;
};
// The columns in the order the CSV and the JSON give them, one per field of CoolingCurve; "a2" (a₂(t)) last,
// only when it evolves.
std::vector<CurveColumn> curve_columns(const CoolingCurve& curve);

}  // namespace restitution::gas
