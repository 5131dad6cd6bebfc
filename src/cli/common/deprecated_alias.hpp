// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// An old spelling of an option, kept for one release: hidden from --help, it warns once on stderr naming the
// new spelling and hands its value to the new option, whose checks and conversion then apply to it.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace restitution::cli {

// `old_name` ("--speeds") as a deprecated spelling of `current` (an option that takes a value) on `command`.
void add_deprecated_alias(CLI::App& command, CLI::Option* current, const std::string& old_name);

// Options that together spell an old form of one new option (`--zeta-min A --zeta-max B` of `--zeta-range
// A:B:N`): hidden from --help, they keep their values and warn once, naming `old_form` and `new_form`.
void deprecate_old_form(const std::vector<CLI::Option*>& old_options, const std::string& old_form,
                        const std::string& new_form);

}  // namespace restitution::cli
