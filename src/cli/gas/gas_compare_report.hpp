// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution gas --compare LOG...` (docs/gas.md, "The LAMMPS deck"): the runs of a gas deck read from
// LAMMPS's logs or screen output, against the kinetic theory (gas_deck/gas_comparison.hpp): the largest
// relative deviation and the late exponents per run, the collision-rate factor measured on the constant-ε
// run, and with an output folder a CSV and the plot (T(t)/T0 and the local exponent, both laws).
#include <filesystem>
#include <string>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "gas_deck/gas_comparison.hpp"

namespace restitution::cli {

// Reads every log (IoError naming one that cannot be read; InvalidInput when none holds a deck's lines).
gas_deck::GasComparison compare_logs(const std::vector<std::string>& logs, const gas_deck::GasSetup& setup);

void print_comparison_text(const gas_deck::GasComparison& c);
void write_comparison_json(JsonWriter& json, const gas_deck::GasComparison& c);
// FOLDER/gas_compare.csv and FOLDER/gas_compare.png; returns the plot's warning ("" when drawn).
std::string write_comparison_files(const std::filesystem::path& folder, const gas_deck::GasComparison& c);

}  // namespace restitution::cli
