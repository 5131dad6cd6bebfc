// SPDX-License-Identifier: BSD-3-Clause
#include "restitution/head_on_parameters.hpp"

#include <utility>

#include "restitution/parameter_rows.hpp"

// A row leaves out what it does not use. GCC 12 crashes on defaults of class type in a class template
// (ParameterField's words and range), so those have none and -Wextra would name each row that leaves them
// out.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace restitution {
namespace {

using K = FieldKind;
using In = HeadOnInputs;

// What the method help says of each method.
const char* method_note(Method method) {
  switch (method) {
    case Method::bdf:
      return "";
    case Method::adams:
      return "the naive end only for zeta <= 2000: its tail is stiff";
    case Method::automatic:
      return "CVODE, chosen per regime";
    case Method::taylor:
      return "Taylor series: about 9x faster than auto at the same tolerance, bench/RESULTS.md; the naive "
             "end "
             "only for zeta <= 100";
  }
  return "";
}

std::string tolerance_help() {
  std::string ranges;
  for (const std::string& r : tolerance_ranges()) ranges += (ranges.empty() ? "" : "; ") + r;
  return "accuracy of eps relative to min(eps, 1 - eps) (read eps when eps is small, one_minus_eps when eps "
         "is near 1): in " +
         ranges;
}

std::vector<HeadOnField> make_head_on_fields() {
  std::vector<HeadOnField> fields = {
      law_field(&In::law),
      {.name = "end",
       .kind = K::word,
       .unit = "",
       .help = "end of the collision: naive (x = 0), delayed-recovery (force = 0) or both",
       .word = &In::end,
       .words = end_set_names(),
       .check_word = [](const std::string& word) { (void)end_set_from_name(word); },
       .show_default = true,
       .scene_key = ""},  // a scene's sections take `ends`, a list
      {.name = "tolerance",
       .kind = K::number,
       .unit = "",
       .help = tolerance_help(),
       .number = &In::tolerance,
       .show_default = true,
       .scene_key = ""},  // a scene's accuracy is the scene's own `tolerance`
      {.name = "method",
       .kind = K::word,
       .unit = "",
       .help = "integration method: " + method_choices(method_note),
       .word = &In::method,
       .words = method_names(),
       .check_word = [](const std::string& word) { (void)method_from_name(word); },
       .show_default = true,
       .scene_key = ""},  // and so is its method
  };
  for (const auto& [name, member] :
       {std::pair{"young_modulus", &In::young_modulus_pa}, std::pair{"poisson_ratio", &In::poisson_ratio},
        std::pair{"radius", &In::radius_m}, std::pair{"radius2", &In::radius2_m},
        std::pair{"density", &In::density_kg_m3}, std::pair{"mass", &In::mass_kg},
        std::pair{"mass2", &In::mass2_kg}}) {
    fields.push_back(material_field(name, member));
  }
  return fields;
}

}  // namespace

const std::vector<HeadOnField>& head_on_fields() {
  static const std::vector<HeadOnField> fields = make_head_on_fields();
  return fields;
}

const HeadOnField& head_on_field(std::string_view name) {
  return field_named(head_on_fields(), name, "head-on");
}

SolveOptions solve_options_of(const HeadOnInputs& in) {
  SolveOptions options;
  options.ends = end_set_from_name(in.end);
  options.tolerance = in.tolerance;
  options.method = method_from_name(in.method);
  return options;
}

}  // namespace restitution
