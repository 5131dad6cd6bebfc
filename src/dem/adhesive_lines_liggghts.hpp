// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// LIGGGHTS 3.8.0's `pair gran` lines for a cohesive pair: `model hertz/stiffness` (kn = (4/3)E*, gamman =
// damp) with `cohesion sjkr` (cohesionEnergyDensity k_c), and what they give under LIGGGHTS's own rules: ε at
// the requested speeds and the sticking speed (docs/adhesion.md §10). The cohesion acts only while the
// spheres overlap and vanishes at δ = 0 with the area, so the contact ends where Hertz's does.
#include <string>
#include <vector>

#include "restitution/adhesion.hpp"

namespace restitution::dem {

struct AdhesiveLiggghtsRequest {
  AdhesiveContact contact;  // model sjkr; the damping is LIGGGHTS's gamman [1/(m s)]
  // Impact speeds [m/s]; empty: 0.97 ... 100 times the sticking speed (needs damping).
  std::vector<double> speeds;
  double tolerance = kDefaultTolerance;
};

struct AdhesiveLiggghtsLines {
  std::vector<std::string> lines;
  double skin_m = 0.0;
  double timestep_s = 0.0;
  StickingSpeed sticking;
  std::vector<double> speeds;
  std::vector<AdhesiveCollision> collisions;
};

// Throws InvalidInput for another model than sjkr, or for no speeds where the spheres never stick.
[[nodiscard]] AdhesiveLiggghtsLines adhesive_liggghts_lines(const AdhesiveLiggghtsRequest& request);

}  // namespace restitution::dem
