// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The checks every study's parameter table (restitution/parameter_table.hpp) passes, shared by
// test_gas_parameters.cpp, test_oblique_parameters.cpp and test_dem_parameters.cpp: each row complete, and a
// value inside (and one outside) the row's range, written as an option's argument or a scene's TOML, read
// back from its member.
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>
#include <vector>

#include "cli/common/parameter_options.hpp"
#include "restitution/errors.hpp"
#include "restitution/parameter_table.hpp"

namespace restitution::table_checks {

template <class In>
int members_set(const ParameterField<In>& f) {
  return int{f.optional_number != nullptr} + int{f.number != nullptr} + int{f.whole_number != nullptr} +
         int{f.word != nullptr} + int{f.flag != nullptr} + int{f.numbers != nullptr};
}

// The row's member is the one its kind says, and only that one; a word with choices checks them.
template <class In>
void expect_complete(const ParameterField<In>& f) {
  SCOPED_TRACE(f.name);
  EXPECT_FALSE(std::string(f.name).empty());
  EXPECT_EQ(std::string(f.name).find_first_not_of("abcdefghijklmnopqrstuvwxyz_0123456789"),
            std::string::npos);
  EXPECT_FALSE(f.help.empty());
  EXPECT_NE(f.unit, nullptr);
  const bool one = members_set(f) == 1;
  switch (f.kind) {
    case FieldKind::optional_number:
      EXPECT_TRUE(f.optional_number != nullptr && one);
      break;
    case FieldKind::number:
      EXPECT_TRUE(f.number != nullptr && one);
      break;
    case FieldKind::whole_number:
      EXPECT_TRUE(f.whole_number != nullptr && one);
      EXPECT_TRUE(f.range.has_value());
      break;
    case FieldKind::word:
    case FieldKind::optional_word:
      EXPECT_TRUE(f.word != nullptr && one);
      if (f.check_word == nullptr) break;  // checked by the study's own rules when it runs
      EXPECT_FALSE(f.words.empty());
      for (const std::string& w : f.words) EXPECT_NO_THROW(f.check_word(w)) << w;
      EXPECT_THROW(f.check_word("no such word"), InvalidInput);
      break;
    case FieldKind::flag:
      EXPECT_TRUE(f.flag != nullptr && one);
      break;
    case FieldKind::numbers:
      EXPECT_TRUE(f.numbers != nullptr && one);
      break;
    case FieldKind::number_or_word:
      EXPECT_EQ(members_set(f), 0);  // read by the study's own code
      EXPECT_FALSE(f.words.empty());
      break;
  }
  if (f.range) EXPECT_FALSE(f.range->text.empty());
  if (f.kind == FieldKind::numbers && !f.required) EXPECT_NE(f.absent, nullptr);
}

// A value inside the row's range (or one of its words), as an option's argument; a flag's is "true".
template <class In>
std::string valid_value(const ParameterField<In>& f) {
  if (!f.words.empty()) return f.words.back();
  if (f.kind == FieldKind::word) return "some-word";
  if (f.kind == FieldKind::flag) return "true";
  if (f.kind == FieldKind::whole_number) return "7";
  if (f.range && f.range->high) return std::to_string(0.5 * (f.range->low + *f.range->high));
  return f.range ? std::to_string(f.range->low + 3.5) : "3.5";
}

// The value as TOML: a word quoted, a list in brackets.
template <class In>
std::string toml_value(const ParameterField<In>& f, const std::string& value) {
  if (f.kind == FieldKind::word || f.kind == FieldKind::optional_word) return "\"" + value + "\"";
  if (!f.words.empty() && value == f.words.back()) return "\"" + value + "\"";
  if (f.kind == FieldKind::numbers) return "[" + value + "]";
  return value;
}

// What the value became in the member, as text; `own` for a number_or_word.
template <class In>
std::string read_back(const ParameterField<In>& f, const In& in, std::string (*own)(const In&) = nullptr) {
  if (f.optional_number) return in.*f.optional_number ? std::to_string(*(in.*f.optional_number)) : "none";
  if (f.number) return std::to_string(in.*f.number);
  if (f.whole_number) return std::to_string(in.*f.whole_number);
  if (f.word) return in.*f.word;
  if (f.flag) return in.*f.flag ? "true" : "false";
  if (f.numbers) return (in.*f.numbers).size() == 1 ? std::to_string((in.*f.numbers)[0]) : "not one value";
  return own(in);
}

template <class In>
std::string expected(const ParameterField<In>& f) {
  const std::string v = valid_value(f);
  if (f.kind == FieldKind::whole_number || f.kind == FieldKind::flag || f.kind == FieldKind::word ||
      f.kind == FieldKind::optional_word || !f.words.empty()) {
    return v;
  }
  return std::to_string(std::stod(v));
}

// The row's option given alone to a command made of the table (cli/common/parameter_options.hpp).
template <class In>
void parse_option(CLI::App& app, const ParameterField<In>& f) {
  std::vector<std::string> reversed{option_name(f.name)};  // CLI11 pops the back
  if (f.kind != FieldKind::flag) reversed.insert(reversed.begin(), valid_value(f));
  app.parse(reversed);
}

}  // namespace restitution::table_checks
