// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The gas study's parameters declared once: one row per field of GasInputs (gas_inputs.hpp) with its name,
// member, unit, range and help. Every front end is made from this table: the options of `restitution gas`
// (the name with dashes: --packing-fraction), the keys of a scene's [[gas]] section and the keywords of
// Python's restitution.gas (the name as it is). A new parameter is a member of GasInputs, a row here and its
// use in cooling_request or thermostat_of.
#include <string_view>
#include <vector>

#include "restitution/parameter_table.hpp"
#include "restitution_gas/gas_inputs.hpp"

namespace restitution::gas {

// The table's types (restitution/parameter_table.hpp), shared with the oblique study's table.
using restitution::FieldGroup;
using restitution::FieldKind;
using restitution::FieldRange;
using restitution::option_name;
using GasField = ParameterField<GasInputs>;

// The fields in the order the command's help lists them.
const std::vector<GasField>& gas_fields();
const std::vector<FieldGroup>& gas_field_groups();
// The field of this name; throws std::out_of_range for a name the table lacks.
const GasField& gas_field(std::string_view name);

// GasInputs::a2, a2_of_haff_eps and a2_evolving from a2's word ("haff", "evolving").
void set_sonine_word(GasInputs& inputs, std::string_view word);

}  // namespace restitution::gas
