// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The options `restitution gas` gains for the LAMMPS deck (docs/gas.md, "The LAMMPS deck"): --deck FILE
// (with --particles, --seed, --max-eps-error) writes the deck of the gas the command describes, --compare
// LOG... compares its runs with the theory. The gas command adds them and, when one is given, hands its gas
// (material, law, packing fraction, initial rms speed, duration) to run_gas_deck instead of its own output.
#include <CLI/CLI.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "cli/gas/gas_options.hpp"
#include "gas_deck/lammps_gas_deck.hpp"

namespace restitution::cli {

struct GasDeckOptions {
  std::optional<std::string> deck;            // --deck FILE
  std::vector<std::string> compare;           // --compare LOG...
  std::optional<std::string> compare_output;  // --compare-output FOLDER: CSV and plot
  std::size_t particles = 2000;
  std::uint64_t seed = 1;
  double max_eps_error = 1e-3;
};
void add_gas_deck_options(CLI::App& cmd, GasDeckOptions& o);
[[nodiscard]] bool gas_deck_requested(const GasDeckOptions& o);

// Writes the deck and/or compares the logs for the gas `gas` describes (the viscoelastic Hertz law only: the
// deck needs --young-modulus and --poisson-ratio too); prints text or one JSON object. Returns the exit
// status.
int run_gas_deck(const GasDeckOptions& o, const GasOptions& gas, bool json);

}  // namespace restitution::cli
