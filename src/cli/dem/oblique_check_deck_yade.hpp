// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The oblique part of a YADE check deck (`dem --code yade --yade-version 2023.02a --friction MU --deck FILE`,
// docs/dem.md, "Oblique impacts"): LAMMPS's section (oblique_check_deck.hpp) in YADE's Python: after the
// head-on collisions, a fresh scene with the three printed lines pasted again collides the pair at each
// listed angle, twice (dt = t_c/20000 and t_c/200000), and prints one line per angle:
//
//   restitution-oblique-check code=yade contact=pair angle=30 et_10dt=... et_dt=... et_code=...
//   et_restitution=... diff=...
//
// YADE's MindlinPhys steps are first order in dt too: et_code = (10 et_dt - et_10dt)/9. At LAMMPS's
// t_c/2000 the rest of second order is still 1.1e-5 (1 mm steel at 60 deg); ten times finer it is below
// 1e-6, for 3 s of YADE at six angles.
#include <string>
#include <vector>

#include "cli/dem/dem_oblique.hpp"

namespace restitution::cli {

// The section for `r` (yade_pair_oblique) and the three YADE lines it was read from.
std::string yade_oblique_check_section(const DemOblique& r, const std::vector<std::string>& lines);

}  // namespace restitution::cli
