// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A study's table (restitution/parameter_table.hpp) as a scene section's keys: each row's key read into its
// member, range-checked (a number's default too) and refused in the table's words, and the table's groups
// (two keys that go together, or exactly one of two). A row the section reads its own way (a material's
// field, a number_or_word, a key of its own) is left to the section.
#include <fmt/core.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "restitution/errors.hpp"
#include "restitution/parameter_table.hpp"
#include "scene/toml_reader.hpp"

namespace restitution::scene::detail {

template <class Inputs>
void read_parameter_word(TomlReader& r, const ParameterField<Inputs>& f, Inputs& in) {
  const auto word = r.text(f.key());
  if (!word) return;
  if (f.check_word != nullptr) {
    try {
      f.check_word(*word);
    } catch (const InvalidInput& e) {
      r.fail(f.key(), e.what());
    }
  }
  in.*f.word = *word;
}

template <class Inputs>
void read_parameter_numbers(TomlReader& r, const ParameterField<Inputs>& f, Inputs& in) {
  const auto values = r.numbers(f.key());
  if ((!values || values->empty()) && f.required) r.fail(f.key(), fmt::format("missing: {}", f.required));
  if (!values) return;
  if (values->empty()) r.fail(f.key(), fmt::format("empty: leave the key out for {}", f.absent));
  if (f.range)
    r.check_each(
        f.key(), *values, [&](double v) { return f.range->contains(v); }, f.range->text);
  in.*f.numbers = *values;
}

template <class Inputs>
void read_parameter_number(TomlReader& r, const ParameterField<Inputs>& f, Inputs& in) {
  std::optional<double> value = r.number(f.key());
  if (!value && f.required) r.fail(f.key(), fmt::format("missing: {}", f.required));
  if (f.kind == FieldKind::number && !value) value = in.*f.number;  // the default is checked too
  if (value && f.range) {
    const bool whole = f.kind == FieldKind::whole_number;
    r.check_each(
        f.key(), {*value}, [&](double v) { return f.range->contains(v) && (!whole || v == std::floor(v)); },
        f.range->text);
  }
  if (value && f.check_number != nullptr) {
    try {
      f.check_number(*value);
    } catch (const InvalidInput& e) {
      r.fail(f.key(), e.what());
    }
  }
  if (!value) return;
  if (f.kind == FieldKind::optional_number) in.*f.optional_number = value;
  if (f.kind == FieldKind::number) in.*f.number = *value;
  if (f.kind == FieldKind::whole_number) in.*f.whole_number = static_cast<int>(*value);
}

// One row's key; false (nothing read) for a row the section reads its own way: no key of the section (a
// material's field) or a number_or_word.
template <class Inputs>
bool read_parameter_key(TomlReader& r, const ParameterField<Inputs>& f, Inputs& in) {
  if (!f.is_key() || f.kind == FieldKind::number_or_word) return false;
  switch (f.kind) {
    case FieldKind::word:
    case FieldKind::optional_word:
      read_parameter_word(r, f, in);
      break;
    case FieldKind::flag:
      if (const auto given = r.flag(f.key())) in.*f.flag = *given;
      break;
    case FieldKind::numbers:
      read_parameter_numbers(r, f, in);
      break;
    default:
      read_parameter_number(r, f, in);  // also refuses a required key's absence and checks a default's range
  }
  return true;
}

// Refuses a pair of optional numbers against its group's rule, at the key the group's message names.
template <class Inputs>
void check_parameter_groups(const TomlReader& r, const std::vector<ParameterField<Inputs>>& fields,
                            const std::vector<FieldGroup>& groups, const Inputs& in) {
  const auto given = [&](const char* name) {
    return (in.*field_named(fields, name, "a grouped").optional_number).has_value();
  };
  for (const FieldGroup& g : groups) {
    const bool first = given(g.first);
    const bool second = given(g.second);
    if (g.rule == FieldGroup::together && first != second) r.fail(first ? g.first : g.second, g.message);
    if (g.rule == FieldGroup::exactly_one && first == second) r.fail(g.first, g.message);
  }
}

}  // namespace restitution::scene::detail
