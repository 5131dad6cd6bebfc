// SPDX-License-Identifier: BSD-3-Clause
#include "gas_deck/gas_log_tokens.hpp"

#include <charconv>
#include <cmath>

namespace restitution::gas_deck {

std::vector<std::string_view> split_tokens(std::string_view line) {
  std::vector<std::string_view> tokens;
  for (std::size_t start = 0;;) {
    const std::size_t space = line.find(' ', start);
    tokens.push_back(line.substr(start, space == std::string_view::npos ? space : space - start));
    if (space == std::string_view::npos) return tokens;
    start = space + 1;
  }
}

std::optional<std::string_view> value_of(std::string_view token, std::string_view key) {
  if (token.size() <= key.size() || token.substr(0, key.size()) != key || token[key.size()] != '=')
    return std::nullopt;
  return token.substr(key.size() + 1);
}

std::optional<double> whole_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc{} || stop != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

std::optional<std::uint64_t> whole_count(std::string_view text) {
  std::uint64_t value = 0;
  const char* end = text.data() + text.size();
  const auto [stop, error] = std::from_chars(text.data(), end, value);
  if (text.empty() || error != std::errc{} || stop != end) return std::nullopt;
  return value;
}

}  // namespace restitution::gas_deck
