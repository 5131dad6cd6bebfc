// SPDX-License-Identifier: BSD-3-Clause
#include "damping_check/damping_check_parameters.hpp"

#include "damping_check/recipes.hpp"

// A row leaves out what it does not use. GCC 12 crashes on defaults of class type in a class template
// (ParameterField's words and range), so those have none and -Wextra would name each row that leaves them
// out.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace restitution::damping_check {
namespace {

using K = FieldKind;
using In = DampingCheckInputs;

// The recipe and the clamp are checked when the check runs (recipe_from_name, clamps_from_name), which
// name the choices; a scene checks each of its recipes with recipe_from_name.
std::vector<DampingCheckField> make_damping_check_fields() {
  return {
      {.name = "recipe",
       .kind = K::word,
       .unit = "",
       .help = "recipe: " + recipe_names(),
       .word = &In::recipe,
       .scene_key = ""},
      {.name = "eps",
       .kind = K::optional_number,
       .unit = "",
       .help = "requested coefficient of restitution in (0, 1)",
       .optional_number = &In::eps,
       .range = FieldRange{.low = 0.0, .high = 1.0, .text = "a value in (0, 1)"},
       .scene_key = ""},
      {.name = "target_eps",
       .kind = K::optional_number,
       .unit = "",
       .help = "the inverse: the eps to request so that the recipe gives this eps at --velocity",
       .optional_number = &In::target_eps,
       .scene_key = ""},
      {.name = "map",
       .kind = K::flag,
       .unit = "",
       .help = "check the requested eps 0.05, 0.10, ..., 0.95, 0.99 instead of --eps",
       .flag = &In::map,
       .scene_key = ""},
      {.name = "clamp",
       .kind = K::word,
       .unit = "",
       .help = "force clamped at zero: on (delayed-recovery end), off (naive end) or both",
       .word = &In::clamp,
       .show_default = true,
       .scene_key = ""},
      {.name = "velocity",
       .kind = K::number,
       .unit = "m/s",
       .help = "reference impact speed in m/s the speed-dependent recipes are set up at (YADE's vn); with "
               "--target-eps the speed of the target",
       .number = &In::velocity_m_s,
       .range = FieldRange{.text = "a value > 0"},
       .show_default = true},
      // A scene's accuracy is the scene's own `tolerance`.
      {.name = "tolerance",
       .kind = K::number,
       .unit = "",
       .help = "accuracy of each eps, in [1e-11, 1e-2]",
       .number = &In::tolerance,
       .show_default = true,
       .scene_key = ""},
  };
}

}  // namespace

const std::vector<DampingCheckField>& damping_check_fields() {
  static const std::vector<DampingCheckField> fields = make_damping_check_fields();
  return fields;
}

const DampingCheckField& damping_check_field(std::string_view name) {
  return field_named(damping_check_fields(), name, "damping check");
}

}  // namespace restitution::damping_check
