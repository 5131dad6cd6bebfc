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
// et_code = (10 et_dt - et_10dt)/9 (the codes are first order in dt here), diff = et_code - et_restitution.
// LIGGGHTS 3.8.0 runs the same commands as LAMMPS (equal-style variables, ${...}, no $(...)); YADE's deck has
// the same section in Python (oblique_check_deck_yade.cpp: a fresh scene with the three printed lines pasted
// again, dt = t_c/20000 and t_c/200000; YADE's MindlinPhys steps are first order in dt too, and at LAMMPS's
// t_c/2000 the rest of second order is still 1.1e-5 for 1 mm steel at 60 deg, ten times finer below 1e-6,
// for 3 s of YADE at six angles); the step choice and the line are shared.
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/dem_codes.hpp"
#include "dem/oblique_lines.hpp"

namespace restitution::dem {

// The tag every oblique check line starts with.
inline constexpr const char* kObliqueCheckTag = "restitution-oblique-check";

// Steps per shortest contact of the coarse pass: the code's entry (CodeEntry::oblique_check_steps, where
// the measurements behind each number are).
int oblique_check_steps_per_contact(Code code);

// The step choice of both passes: dt = t_c/per_contact (t_c the shortest contact), `steps` of it lasting
// 1.1 times the longest contact (the fine pass takes dt/10 and 10 times the steps).
struct ObliqueCheckSteps {
  int per_contact = 0;
  double shortest_contact_s = 0.0;
  double dt_s = 0.0;
  long steps = 0;
};
ObliqueCheckSteps oblique_check_steps(const ObliqueLines& r, int per_contact);

// The section's heading comment (without the comment mark): contact, speed, dt choice.
std::string oblique_check_heading(const ObliqueLines& r, const ObliqueCheckSteps& s);

// The check line of the impact at angle i, the code's measured values as the deck spells them (a LAMMPS
// ${variable}, a Python %-format).
struct ObliqueCheckValues {
  std::string et_10dt, et_dt, et_code, diff;
};
std::string oblique_check_line(const ObliqueLines& r, std::size_t i, const ObliqueCheckValues& values);

// The deck's oblique section for `r` (pair_oblique or wall_oblique; r.code lammps or liggghts) and the lines
// it was read from.
std::string oblique_check_section(const ObliqueLines& r, const std::vector<std::string>& prerequisites,
                                  const std::vector<std::string>& lines);

// The section for `r` (yade_pair_oblique) and the three YADE lines it was read from.
std::string yade_oblique_check_section(const ObliqueLines& r, const std::vector<std::string>& lines);

// The section of the deck's code (its entry's oblique reader) for `r`, read from `deck`.
std::string oblique_check_section(const ObliqueLines& r, const Deck& deck);

}  // namespace restitution::dem
