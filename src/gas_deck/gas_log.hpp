// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reading back what a gas deck (gas_deck/lammps_gas_deck.hpp) printed: LAMMPS's screen output or log file,
// the lines starting with kGasTag, one cooling curve per law.
#include <string>
#include <vector>

namespace restitution::gas_deck {

struct CoolingCurve {
  std::string law;     // "viscoelastic" | "constant-eps"
  std::string source;  // where it was read (a log file's name)
  std::vector<double> time_s, temperature_j;
};

// The curves in `text` in order of first appearance (a log may hold both runs). Lines that are not the
// deck's are skipped (LAMMPS echoes the input: a `print` command itself is not a line the deck printed).
// Throws InvalidInput naming `source` and the line when a tagged line is malformed.
std::vector<CoolingCurve> read_gas_log(const std::string& text, const std::string& source);

// The local exponent d ln T / d ln t at the midpoints of consecutive points (t > 0), geometric mean times.
struct LocalExponent {
  std::vector<double> time_s, exponent;
};
LocalExponent local_exponent(const std::vector<double>& time_s, const std::vector<double>& temperature_j);

}  // namespace restitution::gas_deck
