// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// LIGGGHTS's entry in the table of codes (dem/dem_codes.cpp): its writer and reader, in its own convention
// (docs/dem.md).
#include <cstddef>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::dem {

// The lines and parameters giving `p` the law with A = `a` [s], YADE's vn [m/s], Coulomb mu [1].
void write_liggghts(Deck& d, const Pair& p, double a, double vn, double mu);
// What the deck's parameters give `other`, a pair of the deck's material, read as LIGGGHTS reads them.
Coefficients read_liggghts(const Deck& d, const Pair& other);
// One type's property line: `fix dem_FIX all property/global KEY peratomtypepair 1 VALUE`
// (coefficientFriction is dem_cof's).
std::string liggghts_one_type_line(const std::string& key, double value);
// Several atom types: the lines from every type pair's own deck (pairs I <= J of `n` types, in the order
// of PolydisperseResult::pairs).
std::vector<std::string> liggghts_type_pair_lines(const std::vector<TypePairLines>& pairs, std::size_t n);

}  // namespace restitution::dem
