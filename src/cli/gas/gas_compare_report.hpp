// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution gas --compare LOG...` (docs/gas.md, "The LAMMPS deck"): the runs of a gas deck read from
// LAMMPS's logs or screen output, against the kinetic theory (gas_deck/compared_logs.hpp): the largest
// relative deviation and the late exponents per run, the collision-rate factor measured on the constant-ε
// run, and with an output folder a CSV and the plot (T(t)/T0 and the local exponent, both laws).
#include <filesystem>
#include <string>

#include "cli/common/json_writer.hpp"
#include "gas_deck/compared_logs.hpp"

namespace restitution::cli {

// Says a log's note (what it left out) on stderr, as the logs are read (gas_deck/compared_logs.hpp).
void print_log_note(const std::string& note);

void print_comparison_text(const gas_deck::GasComparison& c);
void write_comparison_json(JsonWriter& json, const gas_deck::GasComparison& c);
// FOLDER/gas_compare.csv and FOLDER/gas_compare.png; returns the plot's warning ("" when drawn).
std::string write_comparison_files(const std::filesystem::path& folder, const gas_deck::GasComparison& c);

}  // namespace restitution::cli
