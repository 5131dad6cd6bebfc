// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Input lines for DEM codes that implement the viscoelastic Hertz law, each in its own convention
// (docs/dem.md), and what those lines give a pair of spheres: the code's own reading of its parameters.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "dem/dem_codes.hpp"
#include "oblique/tangential_models.hpp"
#include "restitution/collision_solver.hpp"
#include "restitution/material.hpp"

namespace restitution::dem {

// The pair of spheres a deck is made for, in SI units.
struct Pair {
  double young_modulus_pa = 0.0;
  double poisson_ratio = 0.0;
  double radius1_m = 0.0, radius2_m = 0.0;
  double mass1_kg = 0.0, mass2_kg = 0.0;
  double effective_modulus_pa = 0.0;  // E*
  double effective_radius_m = 0.0;    // R_eff
  double effective_mass_kg = 0.0;     // m_eff
};
// Validates the material (InvalidInput naming the key); the dissipation fields are ignored.
Pair pair_of(const Material& material);
// The same material at radii scaled by `factor`, masses by factor³ (same density).
Pair scaled(const Pair& pair, double factor);

struct Parameter {
  std::string name;
  double value = 0.0;
  std::string meaning;  // what it is, with its SI unit
};

// LAMMPS's granular tangential model as its writer puts it into the line (pair granular's pair_coeff, or fix
// wall/gran): MODEL [k_t] x_gamma_t mu. The oblique readers take it from here, never from the printed text.
struct GranularTangential {
  oblique::TangentialKind kind = oblique::TangentialKind::linear_nohistory;
  std::optional<double> stiffness;  // k_t in the model's unit (tangential_models.hpp); nullopt: NULL
  double damping_factor = 0.0;      // x_gamma_t
  double friction = 0.0;            // mu
  bool wall = false;                // the line is fix wall/gran's (lines[0]), else pair_coeff (lines[1])
};

struct Deck {
  Code code = kDefaultCode;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  std::vector<Parameter> parameters;
  std::vector<std::string> lines;  // to paste into the code's input
  std::vector<std::string> notes;  // what the lines do and where they stop being exact
  // Input lines the code needs before `lines` (units, atom style, ghost velocities), and the version the
  // lines were run on (tests/dem/); empty for the codes that are libraries.
  std::vector<std::string> prerequisites;
  std::string checked_on;
  // LAMMPS: the tangential model its granular line holds; none for the other codes.
  std::optional<GranularTangential> granular_tangential;
  [[nodiscard]] double parameter(
      std::string_view name) const;  // throws std::out_of_range naming an unknown name
};

// The lines that give `pair` the law with dissipative constant A [s] ending at `end`. `reference_velocity`
// [m/s] is YADE's vn. `friction` is the Coulomb coefficient mu [1] of the tangential model (0: frictionless);
// it never changes the normal law, so the head-on ε is the same for every mu. Throws InvalidInput when the
// code cannot end a collision at `end` or mu is not finite and >= 0 (naming --friction).
// Throws InvalidInput naming --friction unless mu is finite and >= 0.
void check_friction(double mu);
Deck make_deck(Code code, CollisionEnd end, const Pair& pair, double dissipative_constant_s,
               double reference_velocity_m_s, double friction = 0.0);

// β [s^{1/5} m^{-1/5}] the deck's parameters give `other` (a pair of the deck's material), read as the code
// reads them; equals the law's β for the deck's own pair.
double deck_beta(const Deck& deck, const Pair& other);

}  // namespace restitution::dem
