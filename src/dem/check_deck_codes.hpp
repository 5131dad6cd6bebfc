// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The check deck of each code (dem/check_deck.hpp): LAMMPS and LIGGGHTS share one input language, YADE is
// Python. Requests reach these validated by check_deck().
#include <string>

#include "dem/check_deck.hpp"

namespace restitution::dem {

// T = k^{-2/5} v^{-1/5} [s], k = (4/3) E* sqrt(R_eff) / m_eff: the time scale of the pair's collision at
// impact speed v [m/s] (the contact lasts a few T).
double natural_time_s(const Pair& pair, double velocity_m_s);

// The text every deck states at its top: what it does and the format of its check lines, each line
// starting with `comment` ("#").
std::string check_deck_preamble(const CheckDeckRequest& request, int steps_per_time);

std::string lammps_family_check_deck(const CheckDeckRequest& request, int steps_per_time);
std::string yade_check_deck(const CheckDeckRequest& request, int steps_per_time);

}  // namespace restitution::dem
