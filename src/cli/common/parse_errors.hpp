// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Turns CLI11's parse errors into one line that names the option and says what it expected.
#include <CLI/CLI.hpp>
#include <string>

namespace restitution::cli {

// The message with control characters (line breaks from an argument echoed back) shown as '?', so that
// an error stays one line on stderr.
std::string one_line(std::string message);

// The message for a ParseError raised while parsing `app` (the top-level app with its subcommands).
std::string describe_parse_error(const CLI::App& app, const CLI::ParseError& error);

// Adds to every number option of `app` and its subcommands a check of the text as typed: an empty value
// a number beyond the double range (1e309, which CLI11 would turn into inf) and a nonzero number that
// underflows to 0 (1e-400) are refused naming the text; a list option ("FLOAT[,...]") item by item.
void check_number_texts(CLI::App& app);

// "" when the number at the start of `text` is one a double holds (or spells inf/nan: the range checks name
// those), else why not: beyond the range of a double (1e309), or nonzero but read as 0 (1e-400).
std::string number_problem(const std::string& text);

}  // namespace restitution::cli
