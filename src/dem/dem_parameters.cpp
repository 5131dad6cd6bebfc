// SPDX-License-Identifier: BSD-3-Clause
#include "dem/dem_parameters.hpp"

#include "dem/deck.hpp"
#include "restitution/parameter_rows.hpp"

// A row leaves out what it does not use. GCC 12 crashes on defaults of class type in a class template
// (ParameterField's words and range), so those have none and -Wextra would name each row that leaves them
// out.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace restitution::dem {
namespace {

using K = FieldKind;
using In = DemInputs;

// A scene refuses a code or an end in the words the command's own refusal uses.
void check_code(const std::string& name) {
  (void)code_from_name(name);
}

std::vector<DemField> make_dem_fields() {
  return {
      // A scene says what a missing code could be (scene_dem.cpp).
      {.name = "code",
       .kind = K::word,
       .unit = "",
       .help = "DEM code: " + code_list(" or "),
       .word = &In::code,
       .words = code_names(),
       .check_word = check_code},
      {.name = "eps",
       .kind = K::optional_number,
       .unit = "",
       .help = "measured coefficient of restitution in (0, 1): calibrate A first",
       .optional_number = &In::eps,
       .range = FieldRange{.low = 0.0, .high = 1.0, .text = "a value in (0, 1)"}},
      {.name = "velocity",
       .kind = K::optional_number,
       .unit = "m/s",
       .help = "impact speed in m/s at which --eps was measured (required with --eps; also YADE's vn and the "
               "reference speed, 1 m/s with --dissipative-constant)",
       .optional_number = &In::velocity_m_s,
       .range = FieldRange{.text = "a value > 0"}},
      {.name = "dissipative_constant",
       .kind = K::optional_number,
       .unit = "s",
       .help = "the dissipative constant A in s",
       .optional_number = &In::dissipative_constant_s,
       .from_material = true},
      end_field(&In::end),
      {.name = "impact_velocity",
       .kind = K::numbers,
       .unit = "m/s",
       .help = "impact speed(s) in m/s to report eps at, comma-separated (default v/10, v, 10 v)",
       .range = FieldRange{.text = "a value > 0"},
       .required = "the impact speeds to compare at (m/s)",
       .numbers = &In::speeds_m_s,
       .scene_key = "speeds"},
      // A scene's accuracy is the scene's own `tolerance`.
      {.name = "tolerance",
       .kind = K::number,
       .unit = "",
       .help = "accuracy of each eps, in [1e-11, 1e-2]",
       .number = &In::tolerance,
       .show_default = true,
       .scene_key = ""},
      {.name = "friction",
       .kind = K::number,
       .unit = "",
       .help = "Coulomb friction coefficient mu >= 0 of the tangential model (0: frictionless); it does not "
               "change the head-on eps",
       .number = &In::friction,
       .show_default = true,
       .check_number = check_friction},
  };
}

}  // namespace

const std::vector<DemField>& dem_fields() {
  static const std::vector<DemField> fields = make_dem_fields();
  return fields;
}

const DemField& dem_field(std::string_view name) {
  return field_named(dem_fields(), name, "dem");
}

}  // namespace restitution::dem
