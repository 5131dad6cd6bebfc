// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// YADE's entry in the table of codes (dem/dem_codes.cpp): its writer and reader, in its own convention
// (docs/dem.md).
#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::dem {

// The lines and parameters giving `p` the law with A = `a` [s], YADE's vn [m/s], Coulomb mu [1].
void write_yade(Deck& d, const Pair& p, double a, double vn, double mu);
// What the deck's parameters give `other`, a pair of the deck's material, read as YADE reads them.
Coefficients read_yade(const Deck& d, const Pair& other);

}  // namespace restitution::dem
