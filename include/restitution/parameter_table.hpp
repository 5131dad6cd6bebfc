// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A study's parameters declared once: one row per field of the study's inputs struct, with its name, member,
// unit, range and help. The front ends are made from the rows: a command's options (the name with dashes:
// --packing-fraction), a scene section's keys and Python's keywords (the name as it is). The gas study
// (restitution_gas/gas_parameters.hpp), the oblique study (restitution_oblique/oblique_parameters.hpp), the
// DEM lines (src/dem/dem_parameters.hpp) and the damping check
// (src/damping_check/damping_check_parameters.hpp) each hold one table of ParameterField<TheirInputs>. Inline
// only: no module implements it.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace restitution {

enum class FieldKind {
  optional_number,  // std::optional<double>: absent unless given
  number,           // double with a default
  whole_number,     // int with a default
  word,             // std::string with a default (one of words when words is not empty)
  optional_word,    // std::string, empty unless given (one of words)
  number_or_word,   // a number or one of words, read by the study's own code (gas's a2)
  flag,             // bool, false unless given
  numbers,          // std::vector<double>: a list (the command takes it comma-separated)
};

// The range a number must lie in, as a scene states it before anything is computed ("a value > 0"); the
// library's own checks test the same ranges in their words, with the caller's spelling.
struct FieldRange {
  double low = 0.0;
  bool low_open = true;                       // low itself excluded
  std::optional<double> high = std::nullopt;  // none: unbounded above
  bool high_open = true;
  std::string text;     // "a value in (0, 0.5)": the scene's words after "expected"
  bool finite = false;  // also refuses inf (and NaN, which no range holds)
  [[nodiscard]] bool contains(double v) const {
    const bool above = low_open ? v > low : v >= low;
    const bool below = !high || (high_open ? v < *high : v <= *high);
    return above && below && (!finite || std::isfinite(v));
  }
};

template <class Inputs>
struct ParameterField {
  const char* name;  // the scene key and the Python keyword; the option is --name with '-' for '_'
  FieldKind kind;
  const char* unit;  // SI unit of a number ("" when it has none)
  std::string help;  // the option's help, which also documents the key and the keyword
  std::optional<double> Inputs::*optional_number = nullptr;
  double Inputs::*number = nullptr;
  int Inputs::*whole_number = nullptr;
  std::string Inputs::*word = nullptr;
  // No default (= {}) on the members of class type: GCC 12 crashes on them in a class template.
  std::vector<std::string> words;  // the words a word (or number_or_word) takes; empty: checked later
  // A scene's check of a word: throws InvalidInput saying what the key takes (the law's and the end's own
  // refusals, which name the choices). None: the study's own rules check it when it runs.
  void (*check_word)(const std::string& word) = nullptr;
  std::optional<FieldRange> range;
  const char* required =
      nullptr;                 // a scene refuses the section without it (or with an empty list): "missing: "
  bool from_material = false;  // a scene takes it from the section's [materials.X], not from a key
  bool show_default = false;   // the option's help shows its default
  bool Inputs::*flag = nullptr;
  std::vector<double> Inputs::*numbers = nullptr;
  // The scene's key when it is not the name ("angles" for angle); "" when the section reads it its own way.
  const char* scene_key = nullptr;
  const char* absent = nullptr;  // what leaving a list's key out means: a scene refuses an empty list with it
  // A scene's check of a number in the study's own words (the DEM lines' Coulomb mu), as check_word's of a
  // word: throws InvalidInput. None: the range alone.
  void (*check_number)(double value) = nullptr;
  [[nodiscard]] const char* key() const { return scene_key != nullptr ? scene_key : name; }
  [[nodiscard]] bool is_key() const { return !from_material && key()[0] != '\0'; }
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

// The option of a parameter: "--packing-fraction" for packing_fraction.
inline std::string option_name(std::string_view name) {
  std::string option = "--" + std::string(name);
  std::replace(option.begin(), option.end(), '_', '-');
  return option;
}

// The row of this name; throws std::out_of_range naming the study (`what`) for a name the table lacks.
template <class Inputs>
const ParameterField<Inputs>& field_named(const std::vector<ParameterField<Inputs>>& fields,
                                          std::string_view name, std::string_view what) {
  const auto it = std::find_if(fields.begin(), fields.end(),
                               [&](const ParameterField<Inputs>& f) { return f.name == name; });
  if (it == fields.end()) {
    throw std::out_of_range("no " + std::string(what) + " parameter '" + std::string(name) + "'");
  }
  return *it;
}

}  // namespace restitution
