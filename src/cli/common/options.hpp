// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Option vocabulary shared by the subcommands: names on the command line <-> library enums.
#include <fmt/core.h>
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdlib>
#include <string>
#include <vector>

#include "restitution/collision_solver.hpp"
#include "restitution/errors.hpp"
#include "restitution/head_on_parameters.hpp"
#include "restitution/parameter_rows.hpp"
#include "scene/figure_formats.hpp"

namespace restitution::cli {

// An --out/--output value: never empty (an empty path would silently mean "here" or be ignored).
inline CLI::Validator non_empty_path() {
  return {[](const std::string& value) {
            return value.empty() ? std::string("an empty path: give a file or folder name") : std::string();
          },
          "PATH"};
}

// A CLI11 check from a function that throws InvalidInput for a bad value: its message is the usage error.
template <typename Check>
CLI::Validator throwing_check(Check check, const std::string& description) {
  return {[check](const std::string& value) {
            try {
              check(value);
              return std::string();
            } catch (const InvalidInput& e) {
              return std::string(e.what());
            }
          },
          description};
}

// --format png,pdf,svg of the commands that draw figures: the list is checked here (an unknown format is a
// usage error naming it) and read with scene::figure_formats_from_list.
inline CLI::Option* add_figure_format_option(CLI::App* command, std::string& formats) {
  const CLI::Validator known =
      throwing_check([](const std::string& value) { scene::figure_formats_from_list(value); }, "png,pdf,svg");
  return command->add_option("--format", formats, "figure formats, comma-separated: png (300 dpi), pdf, svg")
      ->capture_default_str()
      ->check(known);
}

// --plot FILE of the commands that draw one figure: FILE's extension is its format (png, pdf, svg; see
// scene::figure_format_of), the same rule for every command; any other name is a usage error naming the
// formats that work, never a figure written under another name.
inline CLI::Option* add_plot_option(CLI::App* command, std::string& file, const std::string& what) {
  const CLI::Validator known =
      throwing_check([](const std::string& value) { scene::figure_format_of(value); }, "FILE.png|pdf|svg");
  return command->add_option("--plot", file, what + " (png, pdf or svg, by the file's extension)")
      ->check(known);
}

// A count option: a whole number in [lo, hi], every bound documented; the value as typed in the message
// (a number beyond long long is not silently clamped).
inline CLI::Validator whole_number_in(long long lo, long long hi) {
  return {[lo, hi](const std::string& value) {
            errno = 0;
            char* end = nullptr;
            const long long n = std::strtoll(value.c_str(), &end, 10);
            const bool whole = !value.empty() && *end == '\0' && errno != ERANGE;
            return whole && n >= lo && n <= hi
                       ? std::string()
                       : fmt::format("expected a whole number in [{}, {}], got '{}'", lo, hi, value);
          },
          fmt::format("in [{}, {}]", lo, hi)};
}

// --law NAME, one of law_names() (the family of docs/contact_laws.md).
inline void add_law_option(CLI::App& command, std::string& law) {
  command.add_option("--law", law, law_help())->check(CLI::IsMember(law_names()))->capture_default_str();
}

}  // namespace restitution::cli
