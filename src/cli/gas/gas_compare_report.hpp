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

// Reads every log, streamed (gas_deck::read_gas_log_file), printing its notes on stderr, and checks that each
// run belongs to `setup`: InvalidInput for a missing log, one that is not a regular file, a garbled one, one
// of another gas (naming the field) or when none holds a deck's lines; IoError for one that cannot be read.
gas_deck::GasComparison compare_logs(const std::vector<std::string>& logs, const gas_deck::GasSetup& setup);

void print_comparison_text(const gas_deck::GasComparison& c);
void write_comparison_json(JsonWriter& json, const gas_deck::GasComparison& c);
// FOLDER/gas_compare.csv and FOLDER/gas_compare.png; returns the plot's warning ("" when drawn).
std::string write_comparison_files(const std::filesystem::path& folder, const gas_deck::GasComparison& c);

}  // namespace restitution::cli
