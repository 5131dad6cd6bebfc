// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique study's parameters declared once: one row per field of ObliqueInputs (oblique_study.hpp) with
// its name, member, unit, range and help (restitution/parameter_table.hpp). The front ends are made from
// this table: the options of `restitution oblique` (the name with dashes: --tangential-stiffness), the keys
// of a scene's [[oblique]] section (the row's key: angles, spins) and the keywords of Python's
// restitution.oblique (the name as it is). The material is no row: the command takes the material options
// every command shares, a scene a [materials.X], Python a Material. A new parameter is a member of
// ObliqueInputs, a row here and its use in oblique_setup (oblique_study.cpp).
#include <string_view>
#include <vector>

#include "restitution/parameter_table.hpp"
#include "restitution_oblique/oblique_study.hpp"

namespace restitution::oblique {

using ObliqueField = ParameterField<ObliqueInputs>;

// The fields in the order the command's help lists them.
const std::vector<ObliqueField>& oblique_fields();
// The field of this name; throws std::out_of_range for a name the table lacks.
const ObliqueField& oblique_field(std::string_view name);

}  // namespace restitution::oblique
