// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `--help` within a terminal's 80 columns: CLI11 2.1 prints each option's description on one line however
// long it is (up to 384 columns here). The formatter re-wraps what CLI11 lays out, keeping its two columns.
#include <CLI/CLI.hpp>

#include <cstddef>
#include <string>

namespace restitution::cli {

inline constexpr std::size_t kHelpWidth = 80;

// Each line of `text` longer than `width` broken at spaces. A continuation starts at `description_column`
// when the line is an entry of CLI11's two-column layout (its description starts there) or continues one,
// else two spaces deeper than the line's own indentation. A word longer than the room stays whole.
std::string wrap_help_text(const std::string& text, std::size_t width, std::size_t description_column);

// CLI11's formatter with every help text wrapped to kHelpWidth; set on the top-level app before the
// subcommands are added (they inherit it).
class WrappingHelpFormatter : public CLI::Formatter {
 public:
  std::string make_help(const CLI::App* app, std::string name, CLI::AppFormatMode mode) const override;
};

}  // namespace restitution::cli
