// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// `restitution dem --wall` (docs/dem.md, "Walls"): a sphere hitting a flat wall, rigid or of its own Young's
// modulus and Poisson ratio, and the lines that give that contact the law in the code's WALL convention. The
// contact is the law with E* of sphere and wall (1/E* = (1 - ν²)/Y + (1 - ν_w²)/Y_w, the second term 0 for a
// rigid wall), R* = R and m_eff = m. In Debian's LAMMPS `fix wall/gran granular` reads hertz/material E ν as
// (4/3) E/(2(1 - ν)) (fix_wall_gran.cpp:160), not as the pair's (4/3)/(2(1 - ν²)/E), so the same pair_coeff
// string gives another ε on a wall: the wall's lines carry E = 2(1 - ν) E*.
#include <optional>
#include <string>
#include <vector>

#include "dem/deck.hpp"
#include "dem/lines_check.hpp"
#include "restitution/material.hpp"

namespace restitution::dem {

struct WallMaterial {
  double young_modulus_pa = 0.0;  // Y_w > 0
  double poisson_ratio = 0.0;     // ν_w in (-1, 0.5)
};

struct WallRequest {
  Code code = kDefaultCode;
  CollisionEnd end = CollisionEnd::delayed_recovery;
  Material sphere;                   // Y, ν, radius1, mass1 or density (the second sphere is ignored)
  std::optional<WallMaterial> wall;  // none: a rigid wall
  DampingSource damping;             // A, or ε at v on this wall
  std::vector<double> speeds_m_s;    // empty: v/10, v, 10 v
  double tolerance = SolveOptions{}.tolerance;
  double friction = 0.0;  // Coulomb mu [1]
};

struct WallResult {
  Pair contact;  // E*, R* = R, m_eff = m of the sphere on the wall (radius2, mass2: 0)
  Deck deck;     // the wall's lines, parameters and notes
  double dissipative_constant_s = 0.0;
  double reference_velocity_m_s = 0.0;  // the calibration speed; 1 m/s when A is given
  double friction = 0.0;
  std::vector<SpeedEps> eps;  // what the lines give this sphere on this wall, read as the code reads them
  bool rigid_wall = true;
};

// Throws InvalidInput naming the code when it has no wall lines (every code but LAMMPS), naming the wall's
// modulus or Poisson ratio when out of range, and as `restitution dem` does for the sphere and damping.
WallResult wall_lines(const WallRequest& request);

// The wall check deck (LAMMPS): one sphere per speed, touching a `fix wall/gran` zplane at z = 0 and moving
// onto it, the printed lines pasted unchanged; run at dt = T/n and T/(10 n) (T of the fastest impact), ε =
// v_z'/v from each pass and their Richardson extrapolation, one check line per speed (dem/check_deck.hpp's
// format, types=1,0: atom type 1 on the wall). n = 0: 2000.
std::string wall_check_deck(const WallResult& result, int steps_per_time = 0);

}  // namespace restitution::dem
