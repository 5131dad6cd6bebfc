// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique part of a LAMMPS or LIGGGHTS check deck (`dem --code lammps|liggghts --friction MU --deck
// FILE`, docs/dem.md, "Oblique impacts"): after the head-on collisions, the printed lines pasted again into a
// fresh system that collides the pair (or the sphere and the wall) at each listed angle, twice (dt = t_c/N
// and t_c/(10 N), t_c the shortest contact, N = oblique_check_steps), and prints one line per angle:
//
//   restitution-oblique-check code=lammps contact=pair angle=30 et_10dt=... et_dt=... et_code=...
//   et_restitution=... diff=...
//
// et_code = (10 et_dt - et_10dt)/9 (both codes are first order in dt here), diff = et_code - et_restitution.
// LIGGGHTS 3.8.0 runs the same commands as LAMMPS (equal-style variables, ${...}, no $(...)).
#include <string>
#include <vector>

#include "cli/dem/dem_oblique.hpp"
#include "dem/dem_codes.hpp"

namespace restitution::cli {

// The tag every oblique check line starts with.
inline constexpr const char* kObliqueCheckTag = "restitution-oblique-check";

// Steps per shortest contact of the coarse pass. LAMMPS: 2000 (|diff| <= 2e-7 on 1 mm steel). LIGGGHTS
// decides stick or slip once per step, so its e_t is less smoothly first order: on the 1 mm steel lines of
// docs/dem.md (six angles) the largest |diff| was 8.0e-6 at 2000 and 1.8e-6 at 10000 (its printed steps for
// e_t within 1e-4; glass 1.6e-6, steel at eps 0.98 4.2e-7), so 10000.
int oblique_check_steps(dem::Code code);

// The deck's oblique section for `r` (pair_oblique or wall_oblique; r.code lammps or liggghts) and the lines
// it was read from.
std::string oblique_check_section(const DemOblique& r, const std::vector<std::string>& prerequisites,
                                  const std::vector<std::string>& lines);

}  // namespace restitution::cli
