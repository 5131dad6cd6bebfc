// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The options of `restitution gas` (docs/cli.md, docs/gas.md): one per row of the gas study's table
// (restitution_gas/gas_parameters.hpp), held in the library's GasInputs, and what only the command line has:
// --a2 as written and the second sphere's --radius2 and --mass2, which the monodisperse gas refuses.
#include <CLI/CLI.hpp>
#include <optional>
#include <string>

#include "cli/common/material_options.hpp"
#include "restitution_gas/cooling.hpp"
#include "restitution_gas/driven.hpp"
#include "restitution_gas/gas_inputs.hpp"

namespace restitution::cli {

struct GasOptions {
  gas::GasInputs inputs;
  std::string a2;  // --a2: empty (Maxwellian), a number, haff or evolving
  std::optional<double> radius2, mass2;
};

void add_gas_options(CLI::App& command, GasOptions& o);
// The spheres as the material options give them (the LAMMPS deck's material).
MaterialOptions material_options(const GasOptions& o);
// The request the options describe; throws InvalidInput naming the option that is missing, extra or bad.
gas::CoolingRequest cooling_request(const GasOptions& o);
// The thermostat of --thermostat (none: the freely cooling gas); throws InvalidInput naming the option.
std::optional<gas::Thermostat> thermostat_of(const GasOptions& o);

}  // namespace restitution::cli
