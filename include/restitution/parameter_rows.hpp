// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Rows that several studies' tables (restitution/parameter_table.hpp) share word for word: the material's
// fields (a scene takes them from its [materials.X]), the contact law and the end by name. A table calls the
// maker with its own member; the name, unit, help and check are written here once. Inline only.
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "restitution/contact_law.hpp"
#include "restitution/parameter_table.hpp"
#include "restitution/solve_types.hpp"

namespace restitution {

struct MaterialRowWords {
  const char* name;
  const char* unit;
  const char* help;
};

// The material's fields as the commands take them (--young-modulus ...); radius2 and mass2 are the second
// sphere's, for the studies that take two.
inline const std::vector<MaterialRowWords>& material_row_words() {
  static const std::vector<MaterialRowWords> rows = {
      {"young_modulus", "Pa", "material: Young's modulus Y in Pa"},
      {"poisson_ratio", "", "material: Poisson ratio in (-1, 0.5)"},
      {"radius", "m", "material: sphere radius in m (both spheres unless --radius2)"},
      {"radius2", "m", "material: radius of the second sphere in m"},
      {"density", "kg/m^3", "material: density in kg/m^3 (gives the masses)"},
      {"mass", "kg", "material: sphere mass in kg (instead of --density)"},
      {"mass2", "kg", "material: mass of the second sphere in kg"},
  };
  return rows;
}

// The row of the material field `name` (material_row_words()) read into `member`; throws
// std::out_of_range for a name that is no material field.
template <class Inputs>
ParameterField<Inputs> material_field(std::string_view name, std::optional<double> Inputs::*member) {
  for (const MaterialRowWords& w : material_row_words()) {
    if (name != w.name) continue;
    ParameterField<Inputs> f{};  // {}: no warning for the members a row leaves out
    f.name = w.name;
    f.kind = FieldKind::optional_number;
    f.unit = w.unit;
    f.help = w.help;
    f.optional_number = member;
    f.from_material = true;
    return f;
  }
  throw std::out_of_range("no material field '" + std::string(name) + "'");
}

// "contact law: viscoelastic-hertz, ... or linear-dashpot (docs/contact_laws.md)": every law of law_names().
inline std::string law_help() {
  const std::vector<std::string>& names = law_names();
  std::string list;
  for (std::size_t i = 0; i + 1 < names.size(); ++i) list += (i == 0 ? "" : ", ") + names[i];
  return "contact law: " + list + " or " + names.back() + " (docs/contact_laws.md)";
}

// A word with its choices, checked by `check` (a name's own refusal, which names the choices); its default
// shown.
template <class Inputs>
ParameterField<Inputs> choice_field(const char* name, const std::string& help, std::string Inputs::*member,
                                    const std::vector<std::string>& words,
                                    void (*check)(const std::string&)) {
  ParameterField<Inputs> f{};
  f.name = name;
  f.kind = FieldKind::word;
  f.unit = "";
  f.help = help;
  f.word = member;
  f.words = words;
  f.check_word = check;
  f.show_default = true;
  return f;
}

// `law`: one of law_names(), refused in law_from_name's words.
template <class Inputs>
ParameterField<Inputs> law_field(std::string Inputs::*member) {
  return choice_field("law", law_help(), member, law_names(),
                      [](const std::string& word) { (void)law_from_name(word); });
}

// `end`: one end of the collision (end_names()), refused in end_from_name's words. (Not `eps` and `sweep`'s
// end, which also takes "both".)
template <class Inputs>
ParameterField<Inputs> end_field(std::string Inputs::*member) {
  return choice_field("end", "end of the collision: naive (no clamp) or delayed-recovery (force clamped)",
                      member, end_names(), [](const std::string& word) { (void)end_from_name(word); });
}

}  // namespace restitution
