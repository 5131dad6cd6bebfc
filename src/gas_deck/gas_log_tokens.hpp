// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The tokens of the lines a gas deck prints ("TAG key=value key=value ..."), read strictly: a number is the
// whole token or it is not a number (strtod would take "3.4e-4abc" as 3.4e-4).
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

namespace restitution::gas_deck {

// The tokens of `line` between single spaces (two spaces make an empty token, which no field matches).
std::vector<std::string_view> split_tokens(std::string_view line);

// The value of `token` when it is "key=value", nullopt for another key.
std::optional<std::string_view> value_of(std::string_view token, std::string_view key);

// A finite double spelled by the whole of `text` (no leading '+', space or trailing characters).
std::optional<double> whole_number(std::string_view text);

// A whole number of decimal digits only.
std::optional<std::uint64_t> whole_count(std::string_view text);

}  // namespace restitution::gas_deck
