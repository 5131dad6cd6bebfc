// SPDX-License-Identifier: BSD-3-Clause
#include "cli/common/deprecated_alias.hpp"

#include <fmt/core.h>

#include <cstdio>
#include <functional>
#include <memory>
#include <vector>

namespace restitution::cli {
namespace {

// Prints the warning the first time it is called: one line however often the old spelling is repeated or
// however many list items it carries.
std::function<void()> warning_once(const std::string& old_form, const std::string& new_form) {
  const std::string message = fmt::format(
      "restitution: warning: {} is deprecated and will be removed in 0.5.0; use {}\n", old_form, new_form);
  auto warned = std::make_shared<bool>(false);
  return [message, warned] {
    if (!*warned) std::fputs(message.c_str(), stderr);
    *warned = true;
  };
}

}  // namespace

void add_deprecated_alias(CLI::App& command, CLI::Option* current, const std::string& old_name) {
  const std::function<void()> warn = warning_once(old_name, current->get_name());
  // Forwarded as parsed, so that the values meet the new option's checks and its "given more than once"; as
  // many values per use as the new option takes (`--speeds 0.5 2` as before).
  command
      .add_option_function<std::vector<std::string>>(old_name,
                                                     [warn, current](const std::vector<std::string>& values) {
                                                       warn();
                                                       for (const std::string& value : values) {
                                                         current->add_result(value);
                                                       }
                                                     })
      ->expected(current->get_items_expected_min(), current->get_items_expected_max())
      ->allow_extra_args(current->get_allow_extra_args())
      ->trigger_on_parse()
      ->group("");
}

void deprecate_old_form(const std::vector<CLI::Option*>& old_options, const std::string& old_form,
                        const std::string& new_form) {
  const std::function<void()> warn = warning_once(old_form, new_form);
  for (CLI::Option* option : old_options) {
    option->each([warn](const std::string& /*value*/) { warn(); })->group("");
  }
}

}  // namespace restitution::cli
