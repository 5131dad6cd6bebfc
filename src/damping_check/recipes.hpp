// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What a DEM code's damping recipe makes of a requested coefficient of restitution ε_req: the member of the
// contact-law family it sets (restitution/contact_law.hpp) and its damping ζ in natural units,
//     x'' + ζ x^b x' + x^a = 0,  x(0) = 0, x'(0) = 1,
// for a head-on collision at impact speed v. Every recipe here turns out independent of the material: the
// code's stiffness and mass cancel from ζ (docs/damping.md derives each one). Tsuji-type recipes (b = 1/4)
// give one ζ for every speed; the viscoelastic ones (b = 1/2) give ζ(v) = ζ_ref (v / v_ref)^{1/5}.
#include <array>
#include <string>
#include <string_view>

#include "restitution/collision_solver.hpp"
#include "restitution/contact_law.hpp"

namespace restitution::damping_check {

enum class Recipe {
  lammps_tsuji,
  lammps_viscoelastic,
  liggghts_hertz,
  thornton_2013,
  yade_pade_3_6,
  pade_1_4
};
inline constexpr std::array<Recipe, 6> kRecipes{Recipe::lammps_tsuji,   Recipe::lammps_viscoelastic,
                                                Recipe::liggghts_hertz, Recipe::thornton_2013,
                                                Recipe::yade_pade_3_6,  Recipe::pade_1_4};

// "lammps-tsuji" | "lammps-viscoelastic" | "liggghts-hertz" | "thornton-2013" | "yade-pade-3-6" | "pade-1-4"
const char* recipe_name(Recipe recipe);
// The inverse; throws InvalidInput naming the value and listing every recipe.
Recipe recipe_from_name(std::string_view name);
std::string recipe_names();  // "lammps-tsuji, lammps-viscoelastic, ..."
// The code, its option and the source file or paper the recipe is taken from (one line).
const char* recipe_source(Recipe recipe);

// The formulas, each as its source writes it (docs/damping.md).
double lammps_tsuji_alpha(double eps);  // LAMMPS `damping tsuji`: α(e), a sixth-degree polynomial
double liggghts_beta(double eps);       // LIGGGHTS `model hertz`: β = ln e / sqrt(ln² e + π²) <= 0
double thornton_2013_damping_ratio(double eps);  // Thornton et al. 2013, Eqs. (B6), (B7): the ratio γ
double pade_1_4_sigma(double eps);  // σ with Müller–Pöschel 2011 Padé [1/4](σ) = e (getA.py)

struct RecipeSetting {
  Recipe recipe = Recipe::lammps_tsuji;
  LawKind law = LawKind::tsuji_hertz;
  double code_value = 0.0;  // the number the code derives from ε_req (α, β, γ, σ or ζ_ref)
  const char* code_value_name = "";
  double zeta_reference = 0.0;  // natural ζ at the reference speed (the only ζ when speed_independent)
  // ε does not depend on the impact speed (the member's ζ has speed exponent 0).
  [[nodiscard]] bool speed_independent() const { return restitution::speed_independent(law); }
  // ζ at impact speed v [m/s] for a recipe set up at reference speed v_ref [m/s].
  [[nodiscard]] double zeta_at(double velocity_m_s, double reference_velocity_m_s) const;
};

// The setting for ε_req in (0, 1) (InvalidInput otherwise). lammps-viscoelastic has no ε input in LAMMPS:
// its η_n0 is the one `restitution dem --code lammps` calibrates at the reference speed for the
// delayed-recovery end (clamp on), found here with the solver at `tolerance`.
RecipeSetting recipe_setting(Recipe recipe, double eps_requested, double tolerance, CollisionSolver& solver);

}  // namespace restitution::damping_check
