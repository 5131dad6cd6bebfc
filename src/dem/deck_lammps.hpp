// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// LAMMPS's entry in the table of codes (dem/dem_codes.cpp): its writer and reader, in its own convention
// (docs/dem.md).
#include <cstddef>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::dem {

// The lines and parameters giving `p` the law with A = `a` [s], YADE's vn [m/s], Coulomb mu [1].
void write_lammps(Deck& d, const Pair& p, double a, double vn, double mu);
// The `fix wall/gran granular` line giving a sphere on a wall (`contact`: E*, R* = R, m_eff = m; G* [Pa]) the
// law with A = `a` [s], Coulomb mu, in the wall's own convention (fix_wall_gran.cpp, docs/dem.md "Walls").
void write_lammps_wall(Deck& d, const Pair& contact, double shear_modulus_pa, double a, double mu);
// MODEL [k_t or NULL] x_gamma_t mu, as LAMMPS's granular line spells `t`.
std::string granular_tangential_words(const GranularTangential& t);
// The deck's granular line (pair_coeff, or fix wall/gran when t.wall) with `t` as its tangential model, the
// other numbers the deck's parameters E, eta_n0 and nu.
std::string granular_line(const Deck& d, const GranularTangential& t);
// Puts `t` into the deck: its record and its line.
void set_granular_tangential(Deck& d, const GranularTangential& t);
// What the deck's parameters give `other`, a pair of the deck's material, read as LAMMPS reads them.
Coefficients read_lammps(const Deck& d, const Pair& other);
// Several atom types: the lines from every type pair's own deck (pairs I <= J of `n` types, in the order
// of PolydisperseResult::pairs).
std::vector<std::string> lammps_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t n);

}  // namespace restitution::dem
