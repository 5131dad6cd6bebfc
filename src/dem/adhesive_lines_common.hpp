// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What every code's adhesive lines share: the listed speeds (default multiples of the sticking speed), one
// adhesive solve per speed, and the rounding of the skin and time step to numbers a user can read.
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"

namespace restitution::dem {

struct AdhesiveSolves {
  StickingSpeed sticking;
  std::vector<double> speeds;
  std::vector<AdhesiveCollision> collisions;
  double shortest_contact_s = 0.0;  // of the bounces; every speed sticks: the longest approach to the turn
  double deepest_m = 0.0;           // the largest compression
};

// Empty speeds: 0.97, 1.03, 1.05, 1.5, 3, 10 and 100 times the sticking speed. Throws InvalidInput when the
// sticking speed is 0 and no speed is given.
[[nodiscard]] AdhesiveSolves solve_listed_speeds(const AdhesiveContact& contact,
                                                 const std::vector<double>& speeds, double tolerance);

// The lines after the pair style, the same in LAMMPS and LIGGGHTS: the neighbour skin [m], rebuilds checked
// every step, NVE for spheres and the time step [s].
[[nodiscard]] std::vector<std::string> integration_lines(double skin_m, double timestep_s);

// Rounds down (up) to two significant digits.
[[nodiscard]] double round_down_2(double x);
[[nodiscard]] double round_up_2(double x);

}  // namespace restitution::dem
