// SPDX-License-Identifier: BSD-3-Clause
// LIGGGHTS's lines: hertz/stiffness with per-type-pair kn, kt, gamman, gammat, coefficientFriction matrices.
#include "dem/deck_liggghts.hpp"

#include <fmt/core.h>

#include <cmath>
#include <stdexcept>

#include "dem/deck_notes.hpp"
#include "dem/polydisperse_lines.hpp"
#include "restitution/units.hpp"

namespace restitution::dem {

void write_liggghts(Deck& d, const Pair& p, double a, double /*vn*/, double mu) {
  const double kn = hertz_modulus_pa(p.effective_modulus_pa);
  const double gn = damping_per_mass(a, p.effective_modulus_pa, p.effective_mass_kg);
  d.parameters = {
      {"kn", kn, "k_n = (4/3) E* [Pa], multiplied by sqrt(R_eff xi)"},
      {"gamman", gn, "gamma_n = 2 A E* / m_eff [1/(m s)], multiplied by m_eff sqrt(R_eff xi)"},
  };
  // With friction: Mindlin's k_t = 8 G* (as LIGGGHTS's own `model hertz` computes it) and gamma_t =
  // gamma_n, the same choices as the LAMMPS lines.
  const auto [kt, gt] = tangential(p, kn, gn, mu);
  d.parameters.push_back(
      {"kt", kt, "k_t = 8 G* (Mindlin) [Pa], multiplied by sqrt(R_eff xi); 0: frictionless"});
  d.parameters.push_back({"gammat", gt, "gamma_t = gamma_n [1/(m s)]; 0: frictionless"});
  d.parameters.push_back({"coefficientFriction", mu, "Coulomb friction coefficient [1]"});
  d.lines = {liggghts_one_type_line("kn", kn),
             liggghts_one_type_line("kt", kt),
             liggghts_one_type_line("gamman", gn),
             liggghts_one_type_line("gammat", gt),
             liggghts_one_type_line("coefficientFriction", mu),
             fmt::format("pair_style gran model hertz/stiffness tangential {} limitForce {}",
                         mu > 0.0 ? "history" : "no_history",
                         d.end == CollisionEnd::delayed_recovery ? "on" : "off"),
             "pair_coeff * *"};
  d.prerequisites = {"units si", "atom_style granular", "newton off", "communicate single vel yes"};
  d.checked_on = "LIGGGHTS 3.8.0 (Debian's liggghts 3.8.0+repack1)";
  d.notes = {"the prerequisites matter: under other units than si the numbers model another material",
             mu > 0.0 ? "tangential history: kt = 8 G* (Mindlin), gammat = gamman"
                      : "kt = gammat = coefficientFriction = 0: frictionless",
             friction_note(mu), clamp_note(d.code, d.end),
             "gamman contains 1/m_eff: exact only for the pair it was made for (" + pair_note(p) +
                 "); other pairs get A' = A m_eff' / m_eff"};
}

std::string liggghts_one_type_line(const std::string& key, double value) {
  return fmt::format("fix dem_{} all property/global {} peratomtypepair 1 {}",
                     key == "coefficientFriction" ? "cof" : key, key, num(value));
}

Coefficients read_liggghts(const Deck& d, const Pair& other) {
  const double sqrt_r = std::sqrt(other.effective_radius_m);
  return {d.parameter("kn") * sqrt_r, d.parameter("gamman") * other.effective_mass_kg * sqrt_r};
}

// Several atom types: each type pair's parameters gathered into symmetric per-type-pair matrices.
std::vector<std::string> liggghts_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t n) {
  std::vector<std::string> lines;
  for (const auto& [fix, name] :
       {std::pair{"dem_kn", "kn"}, std::pair{"dem_kt", "kt"}, std::pair{"dem_gamman", "gamman"},
        std::pair{"dem_gammat", "gammat"}, std::pair{"dem_cof", "coefficientFriction"}}) {
    std::string line = fmt::format("fix {} all property/global {} peratomtypepair {}", fix, name, n);
    // Row I, column J: LIGGGHTS reads the n x n matrix row by row.
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = 0; j < n; ++j) {
        line += ' ';
        line += num(pairs[pair_index(i, j, n)].deck.parameter(name));
      }
    }
    lines.push_back(line);
  }
  // The pair_style and pair_coeff lines do not depend on the pair.
  lines.push_back(pairs.front().deck.lines.at(5));
  lines.push_back(pairs.front().deck.lines.at(6));
  return lines;
}

}  // namespace restitution::dem
