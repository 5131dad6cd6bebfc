// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The check deck of each code (dem/check_deck.hpp): LAMMPS and LIGGGHTS share one input language, YADE is
// Python. Requests reach these validated by check_deck().
#include <string>
#include <vector>

#include "dem/check_deck.hpp"

namespace restitution::dem {

// T = k^{-2/5} v^{-1/5} [s], k = (4/3) E* sqrt(R_eff) / m_eff: the time scale of the pair's collision at
// impact speed v [m/s] (the contact lasts a few T).
double natural_time_s(const Pair& pair, double velocity_m_s);

// The comment every deck starts with ("#" lines: LAMMPS's and Python's comments alike): how to run it, what
// it does with n coarse steps per natural time, and the format of its check lines.
std::string check_deck_preamble(const CheckDeckRequest& r, int n);

// LAMMPS, LIGGGHTS: one pass builds the system from scratch (every type pair at every speed, a row each: pair
// by pair, speed by speed), pastes the lines, and runs `steps` at `dt` [s]; then variables rc_eps<row> and
// rc_gap<row> [m] give each row's ε and the gap between its surfaces. The time step for coarse steps per
// natural time n: the shortest collision sets dt = T/n, the longest the length of the run.
struct TimeStep {
  double dt_s = 0.0;
  long steps = 0;
};
TimeStep lammps_family_time_step(const CheckDeckRequest& r, int n);
// Where the collisions sit: a square grid in the y-z plane, `spacing_m` (4 largest radii) apart, each pair
// touching at x = 0 and closing along x, so no sphere ever reaches another collision's. The box holds the
// grid and, along x, the farthest a sphere flies in the run: it grows with the square root of the number of
// collisions, not with the number, and keeps the codes' bins (neighbour lists, atom sorting) few.
struct Layout {
  double reach_m = 0.0;                 // the largest radius
  double spacing_m = 0.0;               // between neighbouring collisions
  std::size_t columns = 1;              // collisions per row along y; row k at z = k spacing
  double half_width_m = 0.0;            // the box along x: [-half_width, half_width]
  double y_max_m = 0.0, z_max_m = 0.0;  // the box along y and z: [-spacing/2, max]
};
Layout lammps_family_layout(const CheckDeckRequest& r, double run_s);
std::string lammps_family_pass(const CheckDeckRequest& r, double dt, long steps);
// The whole deck: both passes (dt = T/n, then T/(10 n)) and the check lines.
std::string lammps_family_check_deck(const CheckDeckRequest& r, int n);

// A Python list [a, b, c] of `values`, each in the shortest form that reads back to the same double (nan and
// inf as float('nan'), float('inf')).
std::string python_list(const std::vector<double>& values);

// InvalidInput unless `lines` are the three YADE lines (material, Ip2, Law2).
void require_yade_lines(const std::vector<std::string>& lines);
// The engines of a YADE collision scene with the Ip2 and Law2 lines (lines[1], lines[2]) in its
// InteractionLoop and NewtonIntegrator(damping=0`newton_extra`), then O.dt = dt and O.run(steps, True):
// indented for a function body, each line ended. The head-on and the oblique check decks share it.
std::string yade_engines_and_run(const std::vector<std::string>& lines, const std::string& newton_extra);

// YADE: the Python function collide(r1, r2, v, dt, steps) -> (eps, gap [m]): a fresh scene with the three
// lines (material, Ip2, Law2) in their places and two touching spheres closing at v, run for `steps` at `dt`.
std::string yade_collide_function(const std::vector<std::string>& lines);
// The whole deck: collide() at dt = T/n and T/(10 n) for every type pair and speed, and the check lines.
std::string yade_check_deck(const CheckDeckRequest& r, int n);

}  // namespace restitution::dem
