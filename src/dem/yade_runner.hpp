// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs YADE (`yade -n -x`) on the lines `restitution dem --code yade` prints, unchanged (in the places the
// check deck puts them: dem/check_deck_codes.hpp), in a head-on collision of the pair at each speed, and
// reads back ε. YADE's leap-frog integrator is first order in dt for a velocity-dependent force: two runs at
// dt = T/n and T/(10 n) (T the natural time of each speed) are Richardson-extrapolated, as for LAMMPS.
#include <string>
#include <vector>

#include "dem/code_runner.hpp"
#include "dem/deck.hpp"

namespace restitution::dem {

// `yade` on PATH, or "" when it is not there.
std::string yade_program();

// The Python script for one run; each speed in a fresh scene, printing "RESTITUTION_EPS index eps gap".
std::string yade_script(const Deck& deck, const Pair& pair, const std::vector<double>& speeds,
                        int steps_per_time);

DemMeasurement measure_yade_eps(const std::string& program, const Deck& deck, const Pair& pair,
                                const std::vector<double>& speeds, int coarse_steps_per_time);

}  // namespace restitution::dem
