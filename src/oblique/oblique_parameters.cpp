// SPDX-License-Identifier: BSD-3-Clause
#include "restitution_oblique/oblique_parameters.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <string>

#include "restitution/solve_types.hpp"

// A row leaves out what it does not use. GCC 12 crashes on defaults of class type in a class template
// (ParameterField's words and range), so those have none and -Wextra would name each row that leaves them
// out.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace restitution::oblique {
namespace {

using K = FieldKind;
using In = ObliqueInputs;

// The normal law's damping and the law: A, or eps at velocity, and which Hertz law.
std::vector<ObliqueField> damping_and_law_fields() {
  return {
      {.name = "dissipative_constant",
       .kind = K::optional_number,
       .unit = "s",
       .help = "the dissipative constant A in s (0: elastic); or --eps and --velocity",
       .optional_number = &In::dissipative_constant_s,
       .from_material = true},
      {.name = "eps",
       .kind = K::optional_number,
       .unit = "",
       .help = "measured coefficient of restitution in (0, 1): A calibrated on this contact (sphere and "
               "sphere, or sphere and wall), head-on at --velocity",
       .optional_number = &In::eps,
       .scene_key = ""},
      {.name = "velocity",
       .kind = K::optional_number,
       .unit = "m/s",
       .help = "impact speed in m/s at which --eps was measured",
       .optional_number = &In::eps_velocity_m_s,
       .scene_key = ""},
      {.name = "law",
       .kind = K::word,
       .unit = "",
       .help = "normal law: viscoelastic-hertz, tsuji-hertz or hertz-constant-damping (the material's "
               "Hertz stiffness; the last two damped by --eps/--velocity; LAMMPS's tangential models)",
       .word = &In::law,
       .show_default = true,
       .scene_key = ""},
  };
}

// The wall and the line of centres.
std::vector<ObliqueField> contact_fields() {
  return {
      {.name = "wall",
       .kind = K::flag,
       .unit = "",
       .help = "a sphere on a flat wall instead of two spheres: rigid, as in `dem --wall`, unless "
               "--wall-young-modulus and --wall-poisson-ratio give its material",
       .flag = &In::wall},
      {.name = "wall_young_modulus",
       .kind = K::optional_number,
       .unit = "Pa",
       .help = "with --wall: the wall's Young's modulus in Pa (default: a rigid wall)",
       .optional_number = &In::wall_young_modulus_pa},
      {.name = "wall_poisson_ratio",
       .kind = K::optional_number,
       .unit = "",
       .help = "with --wall: the wall's Poisson ratio (with --wall-young-modulus)",
       .optional_number = &In::wall_poisson_ratio},
      {.name = "fixed_normal",
       .kind = K::flag,
       .unit = "",
       .help =
           "two spheres: keep the normal of the impact (the textbook model) instead of letting the line of "
           "centres turn as in LAMMPS",
       .flag = &In::fixed_normal},
  };
}

// The tangential model, its stiffness and damping, and friction. A scene sweeps several models (its key
// `model`) and gives k_t per unit (tangential_stiffness in N/m, mindlin_stiffness in N/m^2).
std::vector<ObliqueField> tangential_fields() {
  return {
      {.name = "tangential",
       .kind = K::word,
       .unit = "",
       .help =
           fmt::format("tangential model: {} (docs/oblique.md)", fmt::join(oblique_tangential_names(), ", ")),
       .word = &In::tangential,
       .show_default = true,
       .scene_key = ""},
      {.name = "tangential_stiffness",
       .kind = K::optional_number,
       .unit = "N/m",
       .help = "k_t: N/m for linear_history (required there when friction > 0), N/m^2 for the mindlin "
               "models and liggghts_history (default there: 8 G*)",
       .optional_number = &In::tangential_stiffness,
       .range = FieldRange{.text = "a value > 0 (N/m)", .finite = true}},
      {.name = "tangential_damping",
       .kind = K::number,
       .unit = "",
       .help = "LAMMPS's tangential damping factor (times the normal damping coefficient)",
       .number = &In::tangential_damping,
       .range = FieldRange{.low_open = false, .text = "a value >= 0"},
       .show_default = true},
      {.name = "friction",
       .kind = K::optional_number,
       .unit = "",
       .help = "Coulomb friction coefficient mu",
       .optional_number = &In::friction,
       .range = FieldRange{.low_open = false, .text = "a value >= 0", .finite = true},
       .required = "the Coulomb friction coefficient (0 for a frictionless contact)"},
  };
}

// The impacts: angles, speed, spins (finite: a scene's lists are), the end, the torque arm and the accuracy.
std::vector<ObliqueField> impact_fields() {
  return {
      {.name = "angle",
       .kind = K::numbers,
       .unit = "deg",
       .help = "impact angle(s) from the normal in degrees, in [0, 90)",
       .range = FieldRange{.low_open = false, .high = 90.0, .text = "angles in [0, 90) degrees"},
       .required = "the impact angles from the normal (degrees)",
       .numbers = &In::angles_deg,
       .scene_key = "angles"},
      // A scene reads impact_velocity beside its old name speed until 0.5.0 (scene_oblique.cpp).
      {.name = "impact_velocity",
       .kind = K::number,
       .unit = "m/s",
       .help = "impact speed in m/s",
       .number = &In::speed_m_s,
       .show_default = true,
       .scene_key = ""},
      {.name = "spin",
       .kind = K::numbers,
       .unit = "rad/s",
       .help = "initial spin(s) of the (first) sphere in rad/s (positive adds to the slip); every angle "
               "with every spin",
       .show_default = true,
       .numbers = &In::spins_rad_s,
       .scene_key = "spins",
       .absent = "no initial spin"},
      {.name = "end",
       .kind = K::word,
       .unit = "",
       .help = "end of the collision: naive (no clamp) or delayed-recovery (force clamped)",
       .word = &In::end,
       .words = end_names(),
       .show_default = true},
      {.name = "torque_arm",
       .kind = K::word,
       .unit = "",
       .help =
           "lammps (R - delta/2 for a pair, R for a wall; liggghts_history: R - delta/2 in the torque and "
           "the contact-point velocity), radius or radius-minus-half-overlap",
       .word = &In::torque_arm,
       .words = {"lammps", "radius", "radius-minus-half-overlap"},
       .show_default = true},
      {.name = "tolerance",
       .kind = K::number,
       .unit = "",
       .help = "bound on eps, e_t (absolute), rebound angle (rad) and spins (relative to max(|spin|, v/R)), "
               "in [1e-10, 1e-2)",
       .number = &In::tolerance,
       .range =
           FieldRange{.low = kSmallestObliqueTolerance,
                      .low_open = false,
                      .high = kLargestObliqueTolerance,
                      .text = fmt::format("a value in [{:g}, {:g}) (the accuracy contract, docs/oblique.md)",
                                          kSmallestObliqueTolerance, kLargestObliqueTolerance)},
       .show_default = true},
  };
}

}  // namespace

const std::vector<ObliqueField>& oblique_fields() {
  static const std::vector<ObliqueField> fields = [] {
    std::vector<ObliqueField> all;
    for (auto part : {damping_and_law_fields(), contact_fields(), tangential_fields(), impact_fields()}) {
      all.insert(all.end(), part.begin(), part.end());
    }
    return all;
  }();
  return fields;
}

const ObliqueField& oblique_field(std::string_view name) {
  return field_named(oblique_fields(), name, "oblique");
}

}  // namespace restitution::oblique
