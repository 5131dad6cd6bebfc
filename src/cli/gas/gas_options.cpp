// SPDX-License-Identifier: BSD-3-Clause
#include "cli/gas/gas_options.hpp"

#include <fmt/core.h>
#include <fmt/format.h>

#include <algorithm>
#include <exception>
#include <string>

#include "cli/common/parameter_options.hpp"
#include "restitution/errors.hpp"
#include "restitution/parameter_rows.hpp"
#include "restitution_gas/gas_parameters.hpp"

namespace restitution::cli {
namespace {

// The inputs with --a2's text read: a number, haff or evolving.
gas::GasInputs gas_inputs(const GasOptions& o) {
  if (o.radius2 || o.mass2) {
    throw InvalidInput("--radius2 and --mass2: the gas is of one kind of sphere (monodisperse)");
  }
  gas::GasInputs in = o.inputs;
  const gas::GasField& a2 = gas::gas_field("a2");
  if (o.a2.empty()) return in;
  if (std::find(a2.words.begin(), a2.words.end(), o.a2) != a2.words.end()) {
    gas::set_sonine_word(in, o.a2);
    return in;
  }
  std::size_t used = 0;
  double value = 0.0;
  try {
    value = std::stod(o.a2, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != o.a2.size()) {
    throw InvalidInput(fmt::format("--a2 must be a number, {}, got '{}'", fmt::join(a2.words, " or "), o.a2));
  }
  in.a2 = value;
  return in;
}

}  // namespace

void add_gas_options(CLI::App& command, GasOptions& o) {
  add_parameter_options(command, gas::gas_fields(), o.inputs, [&](const gas::GasField& f, CLI::Option*) {
    if (f.kind == gas::FieldKind::number_or_word) {
      command.add_option(gas::option_name(f.name), o.a2, f.help);  // parsed by gas_inputs
    }
    // The second sphere's options, where the material options list them: refused by the monodisperse gas.
    if (f.optional_number == &gas::GasInputs::radius_m) {
      add_parameter_option(command, material_field("radius2", &GasOptions::radius2), o);
    } else if (f.optional_number == &gas::GasInputs::mass_kg) {
      add_parameter_option(command, material_field("mass2", &GasOptions::mass2), o);
    }
  });
}

MaterialOptions material_options(const GasOptions& o) {
  return material_options_of(o.inputs, o.radius2, o.mass2);
}

gas::CoolingRequest cooling_request(const GasOptions& o) {
  return gas::cooling_request(gas_inputs(o), gas::ArgumentStyle::option);
}

std::optional<gas::Thermostat> thermostat_of(const GasOptions& o) {
  return gas::thermostat_of(gas_inputs(o), gas::ArgumentStyle::option);
}

}  // namespace restitution::cli
