// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The gas a deck was written for, as its input prints it at the start of each run (one line, read back by
// `restitution gas --compare`, which checks that a log belongs to the gas on its command line):
//   restitution-gas-setup law=viscoelastic end=delayed-recovery diameter_m=... mass_kg=...
//   young_modulus_pa=... poisson_ratio=... dissipative_constant_s=... packing_fraction=...
//   initial_temperature_j=...
// Numbers are printed with 10 significant digits, as the deck's other numbers, and compared to that
// precision.
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "gas_deck/lammps_gas_deck.hpp"

namespace restitution::gas_deck {

inline constexpr std::string_view kGasSetupTag = "restitution-gas-setup";

struct GasLogSetup {
  std::string law;  // the run: "viscoelastic" | "constant-eps"
  std::string end;  // "naive" | "delayed-recovery"
  double diameter_m = 0.0;
  double mass_kg = 0.0;
  double young_modulus_pa = 0.0;
  double poisson_ratio = 0.0;
  double dissipative_constant_s = 0.0;  // A of the viscoelastic law (the companion's ε follows from it)
  double packing_fraction = 0.0;
  double initial_temperature_j = 0.0;  // T0 requested, m rms^2
};

// The numeric fields in the order the line prints them, with the options of `restitution gas` that set them.
struct GasLogSetupField {
  std::string_view key;
  double GasLogSetup::*value;
  std::string_view option;
};
inline constexpr std::array<GasLogSetupField, 7> kGasLogSetupFields{{
    {"diameter_m", &GasLogSetup::diameter_m, "--radius"},
    {"mass_kg", &GasLogSetup::mass_kg, "--radius and --density"},
    {"young_modulus_pa", &GasLogSetup::young_modulus_pa, "--young-modulus"},
    {"poisson_ratio", &GasLogSetup::poisson_ratio, "--poisson-ratio"},
    {"dissipative_constant_s", &GasLogSetup::dissipative_constant_s,
     "--dissipative-constant, or --eps and --velocity"},
    {"packing_fraction", &GasLogSetup::packing_fraction, "--packing-fraction"},
    {"initial_temperature_j", &GasLogSetup::initial_temperature_j, "--temperature or --rms-speed"},
}};

// The gas of `request` whose viscoelastic law has the dissipative constant `dissipative_constant_s` (computed
// by the caller: the deck from its lines, --compare from the command's options), for the run `law`.
GasLogSetup gas_log_setup(const GasDeckRequest& request, double dissipative_constant_s, std::string_view law);

// The line the deck prints (without its newline), every number with 10 significant digits.
std::string gas_log_setup_line(const GasLogSetup& setup);

// The setup of a line starting with kGasSetupTag and a space (CR already removed); nullopt unless the line
// holds exactly the fields gas_log_setup_line writes, in its order, each number a whole token.
std::optional<GasLogSetup> parse_gas_log_setup(std::string_view line);

// Throws InvalidInput "--compare SOURCE: the log's FIELD V is not the command's W (OPTION)" for the first
// field (end, then kGasLogSetupFields) where `log` differs from `command` beyond the 10 printed digits.
void check_gas_log_setup(const GasLogSetup& log, const GasLogSetup& command, const std::string& source);

}  // namespace restitution::gas_deck
