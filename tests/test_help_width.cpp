// SPDX-License-Identifier: BSD-3-Clause
// `--help` of the program and of every subcommand fits a terminal's 80 columns (it ran to 384), and the
// wrapping keeps every word and CLI11's two columns.
#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "cli/common/help_format.hpp"
#include "cli_runner.hpp"

namespace {

using restitution::cli::kHelpWidth;
using restitution::cli::wrap_help_text;
using restitution::test_support::lines_of;
using restitution::test_support::run_cli;
using restitution::test_support::subcommands_in;

std::vector<std::string> words_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

TEST(HelpWidth, EveryCommandsHelpFitsEightyColumns) {
  const auto names = subcommands_in(run_cli("--help").out);
  ASSERT_GE(names.size(), 15u) << "the program's --help lists its subcommands";
  std::vector<std::string> commands{""};
  commands.insert(commands.end(), names.begin(), names.end());
  for (const auto& command : commands) {
    const auto r = run_cli(command + " --help");
    ASSERT_EQ(r.status, 0) << command << ": " << r.err;
    ASSERT_FALSE(r.out.empty()) << command;
    for (const auto& line : lines_of(r.out))
      EXPECT_LE(line.size(), kHelpWidth) << "restitution " << command << " --help:\n" << line;
  }
}

TEST(HelpWidth, WrappingKeepsEveryWordAndTheDescriptionColumn) {
  const std::string entry =
      "  --speed FLOAT:POSITIVE      " + std::string(40, 'a') + " the impact speed v [m/s] of " +
      "the two spheres, which with the material gives zeta = beta v^(1/5) (docs/units.md)";
  const std::string wrapped = wrap_help_text(entry + "\n", kHelpWidth, 30);
  EXPECT_EQ(words_of(wrapped), words_of(entry));
  const auto lines = lines_of(wrapped);
  ASSERT_GE(lines.size(), 2u);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    EXPECT_LE(lines[i].size(), kHelpWidth) << lines[i];
    if (i > 0)
      EXPECT_EQ(lines[i].find_first_not_of(' '), 30u) << "a continuation starts in the description column";
  }
  EXPECT_EQ(wrapped.back(), '\n');
}

TEST(HelpWidth, AShortTextIsUnchangedAndALongWordStaysWhole) {
  const std::string text =
      "Usage: restitution eps [OPTIONS]\n\nOptions:\n  -h,--help   Print this help message\n";
  EXPECT_EQ(wrap_help_text(text, kHelpWidth, 30), text);
  const std::string word(100, 'x');
  EXPECT_EQ(wrap_help_text("  " + word, kHelpWidth, 30), "  " + word);
  const std::string choices = "  --law TEXT:{" + std::string(40, 'a') + "," + std::string(40, 'b') + "}=a";
  EXPECT_EQ(wrap_help_text(choices, kHelpWidth, 30),
            "  --law\n    TEXT:{" + std::string(40, 'a') + ",\n    " + std::string(40, 'b') + "}=a")
      << "a list of choices breaks after a comma";
  const std::string footer = "Exit status: " + std::string(70, 'y') + " and more words after the long one";
  const auto lines = lines_of(wrap_help_text(footer + "\n", kHelpWidth, 30));
  ASSERT_EQ(lines.size(), 3u);  // "Exit status:", the long word, the rest
  for (std::size_t i = 1; i < 3; ++i)
    EXPECT_EQ(lines[i].find_first_not_of(' '), 2u) << "a paragraph continues two spaces in";
}

}  // namespace
