// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The gas study's parameters declared once: one row per field of GasInputs (gas_inputs.hpp) with its name,
// member, unit, range and help. Every front end is made from this table: the options of `restitution gas`
// (the name with dashes: --packing-fraction), the keys of a scene's [[gas]] section and the keywords of
// Python's restitution.gas (the name as it is). A new parameter is a member of GasInputs, a row here and its
// use in cooling_request or thermostat_of.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "restitution_gas/gas_inputs.hpp"

namespace restitution::gas {

enum class FieldKind {
  optional_number,  // std::optional<double>: absent unless given
  number,           // double with a default
  whole_number,     // int with a default
  word,             // std::string with a default (one of words, or a law name when words is empty)
  optional_word,    // std::string, empty unless given (one of words)
  number_or_word,   // a2: a number, or one of words (GasInputs::a2, a2_of_haff_eps, a2_evolving)
};

// The range a number must lie in, as a scene states it before anything is computed ("a value > 0"); the
// library's own checks (cooling_request) test the same ranges in their words, with the caller's spelling.
struct FieldRange {
  double low = 0.0;
  bool low_open = true;                       // low itself excluded
  std::optional<double> high = std::nullopt;  // none: unbounded above
  bool high_open = true;
  const char* text = nullptr;  // "a value in (0, 0.5)": the scene's words after "expected"
  [[nodiscard]] bool contains(double v) const;
};

struct GasField {
  const char* name;  // the scene key and the Python keyword; the option is --name with '-' for '_'
  FieldKind kind;
  const char* unit;  // SI unit of a number ("" when it has none)
  std::string help;  // the option's help, which also documents the key and the keyword
  std::optional<double> GasInputs::*optional_number = nullptr;
  double GasInputs::*number = nullptr;
  int GasInputs::*whole_number = nullptr;
  std::string GasInputs::*word = nullptr;
  std::vector<std::string> words = {};  // the words a word (or number_or_word) takes
  // A scene's check of a word: throws InvalidInput saying what the key takes (the law's and the end's own
  // refusals, which name the choices).
  void (*check_word)(const std::string& word) = nullptr;
  std::optional<FieldRange> range = {};
  const char* required = nullptr;  // a scene refuses the section without it: "missing: " this
  bool from_material = false;      // a scene takes it from the section's [materials.X], not from a key
  bool show_default = false;       // the option's help shows its default
};

// Two fields that go together (eps with velocity) or of which exactly one is given (duration or
// haff_times). message: what a scene says at the key `first` (or at `second` when only that one is given
// to a pair that goes together).
struct FieldGroup {
  enum Rule { exactly_one, together };
  const char* first;
  const char* second;
  Rule rule;
  const char* message;
};

// The fields in the order the command's help lists them.
const std::vector<GasField>& gas_fields();
const std::vector<FieldGroup>& gas_field_groups();
// The field of this name; throws std::out_of_range for a name the table lacks.
const GasField& gas_field(std::string_view name);

// The option of a parameter: "--packing-fraction" for packing_fraction.
std::string option_name(std::string_view name);

// GasInputs::a2, a2_of_haff_eps and a2_evolving from a2's word ("haff", "evolving").
void set_sonine_word(GasInputs& inputs, std::string_view word);

}  // namespace restitution::gas
