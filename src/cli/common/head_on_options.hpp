// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The head-on table's rows (restitution/head_on_parameters.hpp) as options of `eps` and `sweep`: each command
// adds the rows it takes, by name, where its help lists them.
#include <CLI/CLI.hpp>
#include <initializer_list>
#include <string_view>

#include "cli/common/material_options.hpp"
#include "cli/common/parameter_options.hpp"
#include "restitution/head_on_parameters.hpp"

namespace restitution::cli {

inline void add_head_on_options(CLI::App& command, HeadOnInputs& in,
                                std::initializer_list<std::string_view> names) {
  for (const std::string_view name : names) add_parameter_option(command, head_on_field(name), in);
}

inline void add_head_on_material_options(CLI::App& command, HeadOnInputs& in) {
  add_head_on_options(command, in,
                      {"young_modulus", "poisson_ratio", "radius", "radius2", "density", "mass", "mass2"});
}

// The material as material_from reads it.
inline MaterialOptions material_options_of(const HeadOnInputs& in) {
  return material_options_of(in, in.radius2_m, in.mass2_kg);
}

}  // namespace restitution::cli
