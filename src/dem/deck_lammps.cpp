// SPDX-License-Identifier: BSD-3-Clause
// LAMMPS's lines: `pair_style granular` with hertz/material and viscoelastic damping; per type pair
// `pair_coeff I J`.
#include "dem/deck_lammps.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "dem/deck_notes.hpp"
#include "dem/polydisperse_lines.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {
namespace {

// mindlin with k_t (nullopt: NULL), x_gamma_t = 1 and mu; frictionless: linear_nohistory 0 0.
GranularTangential frictional_or_not(double mu, std::optional<double> stiffness, bool wall) {
  if (mu > 0.0) return {oblique::TangentialKind::mindlin, stiffness, 1.0, mu, wall};
  return {oblique::TangentialKind::linear_nohistory, std::nullopt, 0.0, 0.0, wall};
}

}  // namespace

std::string granular_tangential_words(const GranularTangential& t) {
  std::string words = oblique::tangential_name(t.kind);
  if (oblique::tangential_model(t.kind).has_stiffness())
    words += " " + (t.stiffness ? num(*t.stiffness) : "NULL");
  return words + " " + num(t.damping_factor) + " " + num(t.friction);
}

std::string granular_line(const Deck& d, const GranularTangential& t) {
  const std::string limit = d.end == CollisionEnd::delayed_recovery ? " limit_damping" : "";
  const std::string material =
      fmt::format("hertz/material {} {} {} tangential {} damping viscoelastic{}", num(d.parameter("E")),
                  num(d.parameter("eta_n0")), num(d.parameter("nu")), granular_tangential_words(t), limit);
  return t.wall ? "fix wall all wall/gran granular " + material + " zplane 0 NULL"
                : "pair_coeff * * " + material;
}

void set_granular_tangential(Deck& d, const GranularTangential& t) {
  d.lines.at(t.wall ? 0 : 1) = granular_line(d, t);
  d.granular_tangential = t;
}

void write_lammps(Deck& d, const Pair& p, double a, double /*vn*/, double mu) {
  const double eta = damping_per_mass(a, p.effective_modulus_pa, p.effective_mass_kg);
  d.parameters = {
      {"E", p.young_modulus_pa,
       "Young's modulus Y [Pa]; LAMMPS mixes two equal types to E* = Y / (2 (1 - nu^2))"},
      {"eta_n0", eta, "damping eta_n0 = 2 A E* / m_eff [1/(m s)], multiplied by m_eff sqrt(R_eff xi)"},
      {"nu", p.poisson_ratio, "Poisson ratio [1]"},
      {"mu_s", mu, "Coulomb friction coefficient [1]"},
  };
  // With friction: Mindlin's k_t = 8 G* a from Y and nu (NULL), the same law family as the normal force,
  // and x_gamma_t = 1, a tangential dashpot as strong as the normal one.
  d.lines = {"pair_style granular", ""};
  set_granular_tangential(d, frictional_or_not(mu, std::nullopt, false));
  d.prerequisites = {"units si", "atom_style sphere", "comm_modify vel yes"};
  d.checked_on = "LAMMPS 29 Sep 2021 - Update 2 (Debian 12's lammps 20220106.git7586adbb6a)";
  d.notes = {
      "the prerequisites matter: under other units than si the numbers model another material, and without "
      "comm_modify vel yes LAMMPS stops (Pair granular requires ghost atoms store velocity)",
      mu > 0.0 ? "tangential mindlin NULL 1 mu: k_t = 8 G* a from Y and nu (Mindlin), x_gamma_t = 1 "
                 "(tangential damping = normal damping)"
               : "tangential linear_nohistory 0 0: frictionless (x_gamma_t = 0, mu_s = 0)",
      friction_note(mu), clamp_note(d.code, d.end),
      "eta_n0 contains 1/m_eff: exact only for the pair it was made for (" + pair_note(p) +
          "); other pairs get A' = A m_eff' / m_eff"};
}

Coefficients read_lammps(const Deck& d, const Pair& other) {
  return {
      hertz_stiffness(effective_modulus_pa(d.parameter("E"), d.parameter("nu")), other.effective_radius_m),
      d.parameter("eta_n0") * other.effective_mass_kg * std::sqrt(other.effective_radius_m)};
}

// Several atom types: each type pair's own pair_coeff line, `* *` made `I J`.
std::vector<std::string> lammps_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t /*n*/) {
  std::vector<std::string> lines{"pair_style granular"};
  const std::string any_pair = "pair_coeff * * ";
  for (const TypePairLines& p : pairs) {
    const std::string& line = p.deck.lines.at(1);
    if (line.rfind(any_pair, 0) != 0) throw std::logic_error("LAMMPS deck without pair_coeff * *: " + line);
    lines.push_back(fmt::format("pair_coeff {} {} {}", p.type1, p.type2, line.substr(any_pair.size())));
  }
  return lines;
}

}  // namespace restitution::dem

namespace restitution::dem {

void write_lammps_wall(Deck& d, const Pair& contact, double shear_modulus_pa, double a, double mu) {
  const double nu = contact.poisson_ratio;
  // fix_wall_gran.cpp:160 makes hertz/material's E into (4/3) E/(2 (1 - nu)): E = 2 (1 - nu) E* gives the
  // wall contact the law's (4/3) E*.
  const double e = 2.0 * (1.0 - nu) * contact.effective_modulus_pa;
  const double eta = damping_per_mass(a, contact.effective_modulus_pa, contact.effective_mass_kg);
  const double kt = 8.0 * shear_modulus_pa;
  d.parameters = {
      {"E", e,
       "the wall's hertz/material E [Pa] = 2 (1 - nu) E*: fix wall/gran makes it (4/3) E/(2 (1 - nu))"},
      {"eta_n0", eta,
       "damping eta_n0 = 2 A E* / m [1/(m s)], multiplied by m sqrt(R xi) (m the sphere's mass)"},
      {"nu", nu, "Poisson ratio [1] (only fixes E's conversion)"},
      {"mu_s", mu, "Coulomb friction coefficient [1]"},
  };
  // With friction a numeric k_t: the wall's `mindlin NULL` is not 8 G* (fix_wall_gran.cpp:248).
  d.lines = {""};
  set_granular_tangential(d, frictional_or_not(mu, kt, true));
  d.prerequisites = {"units si", "atom_style sphere"};
  d.checked_on = "LAMMPS 29 Sep 2021 - Update 2 (Debian 12's lammps 20220106.git7586adbb6a)";
  const std::string convention =
      "fix wall/gran granular: the wall's own convention, not pair granular's; the same pair_coeff string on "
      "a "
      "wall gives another eps (steel: 0.856 on a wall against 0.900 for a pair at 1 m/s)";
  const std::string wallstyle =
      "zplane 0 NULL is an example wall: any wallstyle (xplane, yplane, zcylinder, region) keeps the "
      "numbers; "
      "for a curved wall R* is no longer R";
  d.notes = {convention,
             wallstyle,
             mu > 0.0
                 ? fmt::format("tangential mindlin {} 1 mu: k_t = 8 G* a, G* of sphere and wall, given as a "
                               "number (the wall's NULL gives E (2 - nu)(1 + nu)/4 instead)",
                               num(kt))
                 : "tangential linear_nohistory 0 0: frictionless (x_gamma_t = 0, mu_s = 0)",
             friction_note(mu),
             clamp_note(d.code, d.end),
             "eta_n0 contains 1/m: exact only for the sphere it was made for (R = " +
                 num(contact.effective_radius_m) + " m, m = " + num(contact.effective_mass_kg) +
                 " kg); other spheres get A' = A m' / m"};
}

}  // namespace restitution::dem
