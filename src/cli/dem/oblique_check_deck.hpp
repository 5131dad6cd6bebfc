// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique part of a LAMMPS check deck (`dem --code lammps --friction MU --deck FILE`, docs/dem.md,
// "Oblique impacts"): after the head-on collisions, the printed lines pasted again into a fresh system that
// collides the pair (or the sphere and the wall) at each listed angle, twice (dt = t_c/2000 and t_c/20000,
// t_c the shortest contact), and prints one line per angle:
//
//   restitution-oblique-check code=lammps contact=pair angle=30 et_10dt=... et_dt=... et_code=...
//   et_restitution=... diff=...
//
// et_code = (10 et_dt - et_10dt)/9 (LAMMPS is first order in dt here), diff = et_code - et_restitution.
#include <string>
#include <vector>

#include "cli/dem/dem_oblique.hpp"

namespace restitution::cli {

// The tag every oblique check line starts with.
inline constexpr const char* kObliqueCheckTag = "restitution-oblique-check";
inline constexpr int kObliqueCheckSteps = 2000;  // steps per shortest contact of the coarse pass

// The deck's oblique section for `r` (pair_oblique or wall_oblique) and the lines it was read from.
std::string oblique_check_section(const DemOblique& r, const std::vector<std::string>& prerequisites,
                                  const std::vector<std::string>& lines);

}  // namespace restitution::cli
