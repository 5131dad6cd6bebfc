// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Runs LAMMPS (`lmp`) or LIGGGHTS (`liggghts`), also under an MPI launcher, on head-on collisions of pairs of
// spheres (of one or several atom types) fed the lines `restitution dem` makes, and reads back the ε each
// collision ends with. Used by the [[dem]] scene section
// (dem/code_comparison.hpp) and by the DEM integration tests (tests/dem/).
#include <string>
#include <vector>

#include "dem/deck.hpp"

namespace restitution::dem {

// The program that runs `code` (lmp or liggghts) found on PATH, or "" when it is not there. Throws
// InvalidInput for codes this runner cannot run.
std::string dem_program(Code code);

struct DemRun {
  std::vector<double> eps;    // per speed; NaN where the code printed none
  std::vector<double> gap_m;  // distance between the surfaces at the end (> 0: the collision is over)
  std::string output;         // the program's output, for diagnostics
};

// One head-on collision of a sphere of atom type `type1` with one of `type2` (1-based): radii, masses and
// E*, R_eff, m_eff from `pair`, impact speed in m/s.
struct Collision {
  int type1 = 1, type2 = 1;
  Pair pair;
  double velocity_m_s = 0.0;
};

// A deck of several collisions fed `lines` (what `restitution dem` printed). Each collision is a pair of
// touching spheres, the first at x < 0 and the second at x > 0, closing along x; the pairs lie 10 (R1 + R2)
// apart along y. Time step T_min / steps_per_time, T = k^{-2/5} v^{-1/5} the natural time of a collision,
// run for five natural times of the slowest.
struct CollisionRun {
  Code code = Code::lammps;
  std::vector<std::string> lines;
  int types = 1;  // atom types of the box
  std::vector<Collision> collisions;
  int steps_per_time = 2000;
  std::string processors;  // LAMMPS' processor grid, e.g. "2 1 1" (x < 0 and x > 0 on two ranks); "": none
  std::string after_run;   // commands appended after the run, e.g. a write_dump
};
// `program` may be a launcher with the code, e.g. "mpirun -np 2 lmp".
DemRun run_collisions(const std::string& program, const CollisionRun& run);

// One deck with a pair of touching spheres of type 1 per speed [m/s]: run_collisions of `pair` at each speed.
DemRun run_dem_code(const std::string& program, const Deck& deck, const Pair& pair,
                    const std::vector<double>& speeds, int steps_per_time);

// ε by Richardson extrapolation of two runs at T/n and T/(10 n): both codes use velocity-Verlet, first order
// in the time step for this velocity-dependent force.
struct DemMeasurement {
  std::vector<double> coarse, fine, extrapolated;
  std::vector<double> gap_m;  // of the fine run
  std::string output;         // of the fine run
};
// The extrapolation of a coarse and a fine run (dt ten times smaller), for any code run this way.
DemMeasurement richardson(const DemRun& coarse, const DemRun& fine);
DemMeasurement measure_dem_eps(const std::string& program, const Deck& deck, const Pair& pair,
                               const std::vector<double>& speeds, int coarse_steps_per_time = 2000);
// The extrapolation of `run` at its steps_per_time and at ten times that.
DemMeasurement measure_collisions(const std::string& program, const CollisionRun& run);

}  // namespace restitution::dem
