// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Each code's writer and reader (the table's `write` and `read`, dem/dem_codes.hpp), one file each
// (deck_<code>.cpp), in its own convention derived in docs/dem.md: which numbers make the code's force equal
// to F = (4/3) E* sqrt(R_eff) ξ^{3/2} + 2 A E* sqrt(R_eff ξ) ξ'; and what they share (deck_notes.cpp).
#include <cstddef>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::dem {

void write_lammps(Deck& d, const Pair& p, double a, double vn, double mu);
Coefficients read_lammps(const Deck& d, const Pair& other);
std::vector<std::string> lammps_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t types);

void write_liggghts(Deck& d, const Pair& p, double a, double vn, double mu);
Coefficients read_liggghts(const Deck& d, const Pair& other);
std::vector<std::string> liggghts_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t types);

void write_mercurydpm(Deck& d, const Pair& p, double a, double vn, double mu);
Coefficients read_mercurydpm(const Deck& d, const Pair& other);

void write_yade(Deck& d, const Pair& p, double a, double vn, double mu);
Coefficients read_yade(const Deck& d, const Pair& other);

void write_chrono(Deck& d, const Pair& p, double a, double vn, double mu);
Coefficients read_chrono(const Deck& d, const Pair& other);

// What the writers share (deck_notes.cpp).
// Shortest text that reads back to the same double.
std::string num(double x);
// The law's own coefficients for `p` with A [s].
Coefficients law_coefficients(const Pair& p, double dissipative_constant_s);
// Whether the force is clamped, in words for the notes.
std::string clamp_note(Code code, CollisionEnd end);
// "made for R_eff = .. m, m_eff = .. kg".
std::string pair_note(const Pair& p);
// The tangential spring and dashpot for normal ones (kn, gn) in a code's own units: Mindlin's stiffness and a
// dashpot as strong as the normal one when mu > 0, none when frictionless.
Coefficients tangential(const Pair& p, double kn, double gn, double mu);
// What friction mu does to the head-on ε, in words for the notes.
std::string friction_note(double mu);

}  // namespace restitution::dem
