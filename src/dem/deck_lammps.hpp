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
// What the deck's parameters give `other`, a pair of the deck's material, read as LAMMPS reads them.
Coefficients read_lammps(const Deck& d, const Pair& other);
// Several atom types: the lines from every type pair's own deck (pairs I <= J of `n` types, in the order
// of PolydisperseResult::pairs).
std::vector<std::string> lammps_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t n);

}  // namespace restitution::dem
