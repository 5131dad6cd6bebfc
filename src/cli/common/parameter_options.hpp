// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A study's table (restitution/parameter_table.hpp) as a command's options: one option per row, --name with
// dashes, read into the member the row names, with the row's help, choices and shown default.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "restitution/parameter_table.hpp"

namespace restitution::cli {

// The option of one row, read into `in`; nullptr for a number_or_word row, whose text the command reads.
template <class Inputs>
CLI::Option* add_parameter_option(CLI::App& command, const ParameterField<Inputs>& f, Inputs& in) {
  const std::string option = option_name(f.name);
  CLI::Option* added = nullptr;
  switch (f.kind) {
    case FieldKind::optional_number:
      added = command.add_option(option, in.*f.optional_number, f.help);
      break;
    case FieldKind::number:
      added = command.add_option(option, in.*f.number, f.help);
      break;
    case FieldKind::whole_number:
      added = command.add_option(option, in.*f.whole_number, f.help);
      break;
    case FieldKind::word:
    case FieldKind::optional_word:
      added = command.add_option(option, in.*f.word, f.help);
      if (!f.words.empty()) added->check(CLI::IsMember(f.words));
      break;
    case FieldKind::numbers:
      added = command.add_option(option, in.*f.numbers, f.help)->delimiter(',');
      break;
    case FieldKind::flag:
      return command.add_flag(option, in.*f.flag, f.help);
    case FieldKind::number_or_word:
      return nullptr;
  }
  if (f.show_default) added->capture_default_str();
  return added;
}

// Every row's option in the table's order (the help's); after each, `also(row, its option)` adds what the
// command has beside the table there (gas's --radius2 after --radius, oblique's --angle-range after --angle).
template <class Inputs, class Also>
void add_parameter_options(CLI::App& command, const std::vector<ParameterField<Inputs>>& fields, Inputs& in,
                           Also&& also) {
  for (const ParameterField<Inputs>& f : fields) also(f, add_parameter_option(command, f, in));
}

}  // namespace restitution::cli
