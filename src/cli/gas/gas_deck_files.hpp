// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution gas --deck FILE` (docs/gas.md, "The LAMMPS deck"): the LAMMPS input of the cooling gas written
// to FILE, its constant-ε companion to STEM_constant_eps.EXT and the data file both read to STEM.data, next
// to FILE; written as one set: the previous set stays whole when one cannot be written, and no mixture of two
// sets is ever left, whenever the program is stopped.
#include <filesystem>
#include <string>
#include <vector>

#include "cli/common/json_writer.hpp"
#include "files/output_guards.hpp"
#include "gas_deck/lammps_gas_deck.hpp"

namespace restitution::cli {

struct GasDeckPaths {
  std::filesystem::path law_input, constant_eps_input, data;
};
// Before any work: InvalidInput (exit 2) for an empty name or a folder, IoError (exit 3) when the folder
// cannot be written.
GasDeckPaths gas_deck_paths(const std::string& file);

// Writes the three files as one set (files/file_set.hpp); returns the deck written.
gas_deck::GasDeck write_gas_deck(const GasDeckPaths& paths, const gas_deck::GasDeckRequest& request);

// The three files with the option that names them, for check_outputs_apart.
std::vector<files::NamedPath> gas_deck_outputs(const GasDeckPaths& paths);

void print_gas_deck_text(const GasDeckPaths& paths, const gas_deck::GasDeck& deck,
                         const gas_deck::GasDeckRequest& request);
void write_gas_deck_json(JsonWriter& json, const GasDeckPaths& paths, const gas_deck::GasDeck& deck);

}  // namespace restitution::cli
