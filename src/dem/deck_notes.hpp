// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What the codes' writers share (deck_notes.cpp): numbers as text, the law's own coefficients, the notes on
// clamping, friction and the pair a deck is made for, and the tangential model.
#include <string>

#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::dem {

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
